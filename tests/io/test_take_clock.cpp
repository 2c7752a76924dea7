// One clock for every take (issue 44): a take spans its stack's LocalStart..LocalStop
// where it declares one, else its keys; frame 0 is its start; frames are placed at
// the file's own rate. Fixtures are ASCII FBX written here: three takes on one
// shared timeline whose curves hold every key of it, as 3ds Max and MotionBuilder
// export them, and keys off the frame grid.
#include "fbx_legacy.h"
#include "io_test_util.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"
#include "support/take_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

using test::fbx_text;
using test::shared_timeline_value;

class TakeClock : public ::testing::Test {
 protected:
  test::TempDir dir_;
  std::string write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    test::write_text(path, text);
    return path.string();
  }
};

using test::angle_degrees;
double z_degrees(const Quat& q) { return 2.0 * std::atan2(q.z(), q.w()) * kDegreesPerRadian; }

TEST_F(TakeClock, EachTakeOfASharedTimelineIsItsOwnSpanAtTheFilesRate) {
  const std::string path = write("shared.fbx", test::shared_timeline_fbx());
  struct Expected {
    const char* take;
    std::size_t frames;
    Vec3 first_t, last_t;
    double first_z, last_z;
  };
  for (const Expected& e : {Expected{"anim 1", 21, {0, 0, 0}, {10, 0, 0}, 0, 0},
                            Expected{"anim 2", 16, {10, 0, 0}, {10, 10, 0}, 0, 0},
                            Expected{"spin", 16, {10, 10, 0}, {10, 10, 0}, 0, 180}}) {
    ReadOptions options;
    options.animation = e.take;
    options.read_curves = true;
    Result<ClipFileInfo> info = inspect_clip(path, options);
    ASSERT_TRUE(info.ok()) << info.error();
    const Clip& clip = info->clip;
    EXPECT_EQ(clip.frame_count(), e.frames) << e.take;
    EXPECT_NEAR(clip.frame_time, 1.0 / 30, 1e-12) << e.take;
    EXPECT_EQ(clip.start_time(), 0.0) << e.take;
    const AnimationSummary& s = info->animations.at(info->selected);
    EXPECT_EQ(take_frames(s), e.frames) << e.take;
    EXPECT_TRUE(s.rate_stated) << e.take;
    EXPECT_EQ(s.keys, e.frames) << e.take;
    const TranslationTrack& t = clip.translations.at(0).value();
    EXPECT_LT((t.keys.front() - e.first_t).norm(), 1e-5) << e.take;
    EXPECT_LT((t.keys.back() - e.last_t).norm(), 1e-5) << e.take;
    const RotationTrack& r = clip.rotations.at(0);
    EXPECT_NEAR(std::abs(z_degrees(r.keys.front())), e.first_z, 1e-4) << e.take;
    EXPECT_NEAR(std::abs(z_degrees(r.keys.back())), e.last_z, 1e-4) << e.take;
    EXPECT_NEAR(r.times.back(), (e.frames - 1) / 30.0, 1e-9) << e.take;
  }
}

// info says where each take lies in file time, its length, frames, rate and keys.
TEST_F(TakeClock, InfoShowsEachTakesSpanInFileTime) {
  const std::string path = write("shared.fbx", test::shared_timeline_fbx());
  const test::CliResult r = test::run_cli("info '" + path + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("'anim 2'  0.833333 s to 1.33333 s (0.5 s)  16 frames at 30 Hz (stated by the file)  16 keys"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("'spin'  1.5 s to 2 s (0.5 s)  16 frames at 30 Hz (stated by the file)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frame rate:  30 Hz (frame time 0.0333333333 s), stated by the file"), std::string::npos) << r.out;
}

// `source` evaluates the curves on the clip's clock: at every frame of every take it
// equals the keys assimp baked there.
TEST_F(TakeClock, SourceAndTheBakedKeysAgreeAtEveryFrameOfEveryTake) {
  const std::string path = write("shared.fbx", test::shared_timeline_fbx());
  for (const char* take : {"anim 1", "anim 2", "spin"}) {
    ReadOptions options;
    options.animation = take;
    auto read = read_source_clip(path, options);
    ASSERT_TRUE(read.ok()) << read.error();
    auto source = std::make_shared<const SourceClip>(std::move(*read));
    auto motion = source_motion(source, path);
    ASSERT_TRUE(motion.ok()) << motion.error();
    const RotationTrack& keys = source->clip.rotations.at(0);
    for (std::size_t k = 0; k < keys.times.size(); ++k)
      EXPECT_LT(angle_degrees((*motion)(0, keys.times[k]), keys.keys[k]), 1e-4) << take << " key " << k;
  }
}

// A take without a declared span is its keys' span; keys off the frame grid stay keys,
// and the frames are at the file's own rate.
TEST_F(TakeClock, KeysOffTheGridKeepTheFilesRateAndTheirOwnTimes) {
  const std::vector<double> times = {0.05, 0.21, 0.4, 0.73, 1.05};
  const std::string path = write("offgrid.fbx", fbx_text({{"Take", 0, 0}}, times, shared_timeline_value, true));
  Result<ClipFileInfo> info = inspect_clip(path, {});
  ASSERT_TRUE(info.ok()) << info.error();
  const Clip& clip = info->clip;
  EXPECT_NEAR(clip.frame_time, 1.0 / 30, 1e-12);
  EXPECT_EQ(clip.frame_count(), 31u);  // 1 s at 30 Hz
  ASSERT_EQ(clip.rotations[0].times.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_NEAR(clip.rotations[0].times[k], times[k] - 0.05, 1e-6);
}

// Our own FBX reader (the FBX 6.1 path, which reads 7.x curves too) and the assimp
// path place every take's frames on the same clock, with the same poses.
TEST_F(TakeClock, OurReaderAndAssimpAgreeOnEveryTake) {
  const std::string path = write("shared.fbx", test::shared_timeline_fbx());
  for (const char* take : {"anim 1", "anim 2", "spin"}) {
    ReadOptions options;
    options.animation = take;
    Result<ClipFileInfo> by_assimp = inspect_clip(path, options);
    ASSERT_TRUE(by_assimp.ok()) << by_assimp.error();
    ClipFileInfo ours;
    ASSERT_TRUE(read_legacy_fbx(path, options, ours, {}).ok()) << take;
    const Clip& a = by_assimp->clip;
    const Clip& b = ours.clip;
    EXPECT_EQ(a.frame_count(), b.frame_count()) << take;
    EXPECT_EQ(a.start_time(), b.start_time()) << take;
    const int bone = b.skeleton.find("Bone");
    ASSERT_GE(bone, 0);
    const RotationTrack& ra = a.rotations.at(0);
    const RotationTrack& rb = b.rotations.at(static_cast<std::size_t>(bone));
    ASSERT_EQ(ra.times.size(), rb.times.size()) << take;
    for (std::size_t k = 0; k < ra.times.size(); ++k) {
      EXPECT_NEAR(ra.times[k], rb.times[k], 1e-9) << take;
      EXPECT_LT(angle_degrees(ra.keys[k], rb.keys[k]), 1e-4) << take << " frame " << k;
    }
  }
}

// The same clock over every FBX of the shared data: frame count, start and end. (Their
// poses differ where assimp bakes what our reader evaluates: it interpolates cubic
// curves linearly between the union of a node's key times and does not blend layers;
// `source` replays the curves for that reason.)
TEST(TakeClockShared, OurReaderAndAssimpPlaceEverySharedFbxOnOneClock) {
  std::size_t files = 0;
  for (const char* folder : {"fbx", "curves"})
    for (const auto& file : std::filesystem::directory_iterator(test::kData / folder)) {
      if (file.path().extension() != ".fbx") continue;
      const std::string path = file.path().string();
      Result<ClipFileInfo> by_assimp = inspect_clip(path, {});
      ClipFileInfo ours;
      const Status st = read_legacy_fbx(path, {}, ours, {});
      ASSERT_TRUE(by_assimp.ok()) << by_assimp.error();
      ASSERT_TRUE(st.ok()) << st.error();
      const Clip& a = by_assimp->clip;
      const Clip& b = ours.clip;
      EXPECT_EQ(a.frame_count(), b.frame_count()) << path;
      EXPECT_NEAR(a.frame_time, b.frame_time, 1e-12) << path;
      EXPECT_NEAR(a.start_time(), b.start_time(), 1e-9) << path;
      EXPECT_NEAR(a.end_time(), b.end_time(), 1e-6) << path;
      const AnimationSummary& sa = by_assimp->animations.at(by_assimp->selected);
      const AnimationSummary& sb = ours.animations.at(ours.selected);
      EXPECT_EQ(take_frames(sa), take_frames(sb)) << path;
      EXPECT_EQ(sa.rate_stated, sb.rate_stated) << path;
      ++files;
    }
  EXPECT_GE(files, 15u);
}

}  // namespace
}  // namespace rotinterp
