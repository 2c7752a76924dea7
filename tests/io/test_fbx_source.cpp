// The `source` rotations (io/fbx_source.h): joints evaluated from the FBX file's
// stored curves equal assimp's baked keys where assimp sampled those curves, and
// between keys follow the curves' tangents, which no interpolator of the keys does.
#include "io_test_util.h"
#include "rotinterp/core/geodesic.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/fbx_curve_eval.h"
#include "rotinterp/io/fbx_source.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

double angle_degrees(const Quat& a, const Quat& b) {
  return 2.0 * std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * kDegreesPerRadian;
}

SourceClip read_source(const std::string& relative) {
  auto read = read_source_clip(test::kData / relative, {});
  EXPECT_TRUE(read.ok()) << read.error();
  return read.ok() ? *read : SourceClip{};
}

// Files whose rotations are keyed with cubic tangents (user and spline) and every
// channel of a node keyed at the same times, so that assimp's baked keys are the
// curves' values. The sausage's joint1 has a PreRotation and no pivots: assimp
// bakes the PreRotation into its keys and keeps it in a helper node too, and the
// read counts it once (it was 90° off).
const char* const kKeyedFiles[] = {"fbx/digitalrune_Marine_Run.fbx", "fbx/digitalrune_PlayerMarine_Idle.fbx",
                                   "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx"};

TEST(FbxSource, ReplayedKeysEqualTheKeysAssimpBakedFromTheSameCurves) {
  for (const char* file : kKeyedFiles) {
    SCOPED_TRACE(file);
    const SourceClip source = read_source(file);
    Clip replayed = source.clip;
    auto n = replay_fbx_rotations(replayed, source, {}, file);
    ASSERT_TRUE(n.ok()) << n.error();
    EXPECT_GT(*n, 0u);
    double worst = 0.0;
    for (std::size_t j = 0; j < replayed.rotations.size(); ++j)
      for (std::size_t k = 0; k < replayed.rotations[j].keys.size(); ++k)
        worst = std::max(worst, angle_degrees(replayed.rotations[j].keys[k], source.clip.rotations[j].keys[k]));
    std::printf("%s: %zu joints replayed, worst key difference %.3g°\n", file, *n, worst);
    EXPECT_LT(worst, 1e-2);  // float keys in the file, assimp's float math
  }
}

TEST(FbxSource, BetweenKeysTheCurvesDifferFromEveryInterpolatorOfTheKeys) {
  const SourceClip source = read_source("fbx/digitalrune_Marine_Run.fbx");
  Clip replayed = source.clip;
  // Segment midpoints of every joint's keys, replayed from the curves.
  for (RotationTrack& track : replayed.rotations) {
    if (track.times.size() < 2) continue;
    std::vector<double> mid;
    for (std::size_t k = 0; k + 1 < track.times.size(); ++k) mid.push_back(0.5 * (track.times[k] + track.times[k + 1]));
    track.times = mid;
    track.keys.assign(mid.size(), Quat::Identity());
  }
  ASSERT_TRUE(replay_fbx_rotations(replayed, source, {}, "Marine_Run").ok());
  for (const MethodInfo& m : methods()) {
    double worst = 0.0;
    for (std::size_t j = 0; j < replayed.rotations.size(); ++j) {
      const RotationTrack& baked = source.clip.rotations[j];
      if (baked.times.size() < 2) continue;
      auto interp = m.make(baked);
      ASSERT_TRUE(interp.ok()) << interp.error();
      for (std::size_t k = 0; k < replayed.rotations[j].times.size(); ++k)
        worst = std::max(worst, angle_degrees((*interp)->evaluate(replayed.rotations[j].times[k]),
                                              replayed.rotations[j].keys[k]));
    }
    std::printf("%-10s worst midpoint distance from the curves %.3f°\n", m.name.c_str(), worst);
    EXPECT_GT(worst, 0.1) << m.name;
  }
}

// joint1 of the sausage has PreRotation (0, 0, 90) and a Z curve: its local
// rotation is Rz(90° + curve), once. (Blender's importer agrees: joint2, 1 cm
// along joint1's X, is at 44° in the XY plane at frame 1, where the curve is
// −46.01°.)
TEST(FbxSource, PreRotationIsAppliedOnceBeforeTheEulerCurves) {
  const SourceClip source = read_source("fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx");
  Clip replayed = source.clip;
  ASSERT_TRUE(replay_fbx_rotations(replayed, source, {}, "sausage").ok());
  const FbxTake& take = source.curves.takes.at(source.take);
  const FbxCurve* z = nullptr;
  for (const FbxCurve& c : take.curves)
    if (c.node == "joint1" && c.property == "Lcl Rotation" && c.channel == 'Z') z = &c;
  ASSERT_NE(z, nullptr);
  const int j = replayed.skeleton.find("joint1");
  ASSERT_GE(j, 0);
  const RotationTrack& track = replayed.rotations[static_cast<std::size_t>(j)];
  for (std::size_t k = 0; k < track.times.size(); ++k) {
    const double ticks = static_cast<double>(take.start) + track.times[k] * static_cast<double>(kFbxTicksPerSecond);
    const double degrees = 90.0 + evaluate_fbx_curve(*z, ticks);
    const Quat expected(Eigen::AngleAxisd(degrees / kDegreesPerRadian, Vec3::UnitZ()));
    EXPECT_LT(angle_degrees(track.keys[k], expected), 1e-6) << "key " << k;
  }
}

TEST(FbxSource, ABvhIsRefusedInOneLineNamingTheFile) {
  const auto path = test::kData / "bvh/bvhio_example.bvh";
  auto read = read_source_clip(path, {});
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().find(path.string() + ": --method source replays FBX curves"), std::string::npos) << read.error();
  EXPECT_EQ(read.error().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
