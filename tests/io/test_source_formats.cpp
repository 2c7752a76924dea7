// `source` in every format (io/source_motion.h): glTF files replay their samplers and
// agree with assimp's keys on real skeletons, a BVH's source is its frames, and a
// format with nothing to replay is refused in one line.
#include "rotinterp/io/gltf/gltf_write.h"
#include "io_test_util.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rotinterp {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

using test::angle_degrees;

Clip read(const std::string& relative) {
  auto clip = read_clip(test::kData / relative);
  EXPECT_TRUE(clip.ok()) << clip.error();
  return clip.ok() ? *clip : Clip{};
}

// The largest angle between the replay and the clip's key, over every key of every
// joint the file replays.
double worst_key_difference(const FileSource& source) {
  double worst = 0.0;
  for (std::size_t j = 0; j < source.clip.rotations.size(); ++j) {
    if (!source.own[j]) continue;
    const RotationTrack& track = source.clip.rotations[j];
    for (std::size_t k = 0; k < track.keys.size(); ++k)
      worst = std::max(worst, angle_degrees(source.motion(j, track.times[k]), track.keys[k]));
  }
  return worst;
}

// No GLB is among the shared clips: these are written from them by our glTF writer,
// with LINEAR samplers (every key time) and with CUBICSPLINE rotations at each track's
// own keys (as reduce writes them), then read back through assimp and replayed.
TEST(SourceFormats, OnGlbsWrittenFromTheRealClipsTheReplayEqualsEveryKeyAssimpRead) {
  test::TempDir dir;
  for (const char* file : {"fbx/digitalrune_Marine_Run.fbx", "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh",
                           "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", "fbx/assimp_huesitos.fbx"}) {
    SCOPED_TRACE(file);
    const Clip clip = read(file);
    for (const bool cubic : {false, true}) {
      const auto path = dir / (std::string(cubic ? "cubic_" : "linear_") + std::filesystem::path(file).stem().string() + ".glb");
      const Status written = cubic ? write_gltf(clip, path, true, GltfKeys{true, true, false}) : write_clip(clip, path);
      ASSERT_TRUE(written.ok()) << written.error();
      auto source = read_file_source(path, {});
      ASSERT_TRUE(source.ok()) << source.error();
      const double worst = worst_key_difference(*source);
      std::printf("%s (%s): %zu of %zu joints replayed, worst replay-vs-key %.3g°\n", file, cubic ? "CUBICSPLINE" : "LINEAR",
                  source->own_joints(), source->own.size(), worst);
      EXPECT_EQ(source->own_joints(), clip.skeleton.joints.size());
      EXPECT_LT(worst, 1e-4);
    }
  }
}

// A BVH stores its frames and nothing between them: its source is the clip's keys.
TEST(SourceFormats, ABvhsSourceIsItsFramesAtEveryFrameAndTheirSlerpBetween) {
  auto source = read_file_source(test::kData / "bvh/NC_bandai1_walk_normal_001.bvh", {});
  ASSERT_TRUE(source.ok()) << source.error();
  EXPECT_EQ(source->own_joints(), source->clip.skeleton.joints.size());
  for (std::size_t j = 0; j < source->clip.rotations.size(); ++j)
    for (std::size_t k = 0; k < source->clip.rotations[j].keys.size(); ++k)
      ASSERT_EQ(source->motion(j, source->clip.rotations[j].times[k]).coeffs(), source->clip.rotations[j].keys[k].coeffs());
  const RotationTrack& hips = source->clip.rotations[0];
  const double mid = 0.5 * (hips.times[10] + hips.times[11]);
  EXPECT_LT(angle_degrees(source->motion(0, mid), hips.keys[10].slerp(0.5, hips.keys[11])), 1e-9);
}

// Collada keeps no curves or samplers we read: refused, one line naming the file.
TEST(SourceFormats, AFormatWithNothingToReplayIsRefusedInOneLineNamingTheFile) {
  test::TempDir dir;
  const auto path = dir / "walk.dae";
  ASSERT_TRUE(write_clip(read("bvh/bvhio_example.bvh"), path).ok());
  auto source = read_file_source(path, {});
  ASSERT_FALSE(source.ok());
  EXPECT_NE(source.error().find(path.string() + ": --method source replays a file's own motion (FBX curves, glTF "
                                              "animation samplers, BVH frames); this is a 'dae' file"),
            std::string::npos)
      << source.error();
  EXPECT_EQ(source.error().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
