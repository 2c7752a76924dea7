// The `source` rotations (io/fbx/fbx_source.h): joints evaluated from the FBX file's
// stored curves equal assimp's baked keys where assimp sampled those curves, and
// between keys follow the curves' tangents, which no interpolator of the keys does.
#include "io_test_util.h"
#include "rotinterp/core/geodesic.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace rotinterp {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

using test::angle_degrees;

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
    const double ticks = static_cast<double>(fbx_take_span(take).start) + track.times[k] * static_cast<double>(kFbxTicksPerSecond);
    const double degrees = 90.0 + evaluate_fbx_curve(*z, ticks);
    const Quat expected(Eigen::AngleAxisd(degrees / kDegreesPerRadian, Vec3::UnitZ()));
    EXPECT_LT(angle_degrees(track.keys[k], expected), 1e-6) << "key " << k;
  }
}

// One bone turning about Z, keyed at frames 1, 2, 30, 180 and 359 of 30 fps (the first
// key at 1/30 s, not 0), in a stack that declares no LocalStart/LocalStop: assimp
// re-bases such a take to its first key, so clip time 0 is FBX time 1/30 s.
std::string late_first_key_fbx() {
  const long long frame = 1539538600;  // ticks
  std::string times, values;
  for (int f : {1, 2, 30, 180, 359}) {
    times += (times.empty() ? "" : ",") + std::to_string(f * frame);
    values += (values.empty() ? "" : ",") + std::to_string(1080.0 + 360.0 * (f - 1) / 358.0);
  }
  return "; FBX 7.4.0 project file\n"
         "FBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n"
         "Objects:  {\n"
         "\tModel: 1000, \"Model::Bone\", \"LimbNode\" {\n\t\tVersion: 232\n\t}\n"
         "\tAnimationStack: 2000, \"AnimStack::Take\", \"\" {\n\t}\n"
         "\tAnimationLayer: 3000, \"AnimLayer::Base\", \"\" {\n\t}\n"
         "\tAnimationCurveNode: 4000, \"AnimCurveNode::R\", \"\" {\n\t\tProperties70:  {\n"
         "\t\t\tP: \"d|X\", \"Number\", \"\", \"A\",0\n\t\t\tP: \"d|Y\", \"Number\", \"\", \"A\",0\n"
         "\t\t\tP: \"d|Z\", \"Number\", \"\", \"A\",0\n\t\t}\n\t}\n"
         "\tAnimationCurve: 5000, \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4009\n"
         "\t\tKeyTime: *5 {\n\t\t\ta: " + times + "\n\t\t}\n"
         "\t\tKeyValueFloat: *5 {\n\t\t\ta: " + values + "\n\t\t}\n\t}\n}\n"
         "Connections:  {\n\tC: \"OO\",1000,0\n\tC: \"OO\",3000,2000\n\tC: \"OO\",4000,3000\n"
         "\tC: \"OP\",4000,1000, \"Lcl Rotation\"\n\tC: \"OP\",5000,4000, \"d|Z\"\n}\n";
}

// `source` and the baked keys share one clock: at every key the replayed rotation is the
// key assimp baked (it was one frame off: frames 0 and 1 both the first key's 1080°).
TEST(FbxSource, ATakeWhoseFirstKeyIsNotAtZeroIsReplayedOnTheClipsClock) {
  test::TempDir dir;
  const auto path = dir / "late.fbx";
  test::write_text(path, late_first_key_fbx());
  auto read = read_source_clip(path, {});
  ASSERT_TRUE(read.ok()) << read.error();
  auto source = std::make_shared<const SourceClip>(std::move(*read));
  EXPECT_EQ(fbx_take_span(source->curves.takes.at(source->take)).start, 1539538600);
  auto motion = source_motion(source, "late.fbx");
  ASSERT_TRUE(motion.ok()) << motion.error();
  const Clip& clip = source->clip;
  const auto bone = static_cast<std::size_t>(clip.skeleton.find("Bone"));
  const RotationTrack& keys = clip.rotations[bone];
  // The file's keys at clip times 0, 1/30, 29/30, 179/30 and 358/30 s (assimp adds one
  // of its own before the last, which is not a key of the curve).
  std::size_t matched = 0;
  EXPECT_EQ(keys.times.front(), 0.0);
  for (std::size_t k = 0; k < keys.keys.size(); ++k) {
    const double frame = keys.times[k] * 30.0;
    if (std::abs(frame - std::round(frame)) > 1e-6) continue;
    ++matched;
    EXPECT_LT(angle_degrees((*motion)(bone, keys.times[k]), keys.keys[k]), 1e-4) << "key " << k << " at " << keys.times[k];
  }
  EXPECT_EQ(matched, 5u);
}

// A file that is not FBX has no curves: read_source_clip (the FBX reader behind
// read_file_source, io/source_motion.h, which replays BVH and glTF too) says so in one line.
TEST(FbxSource, ReadingCurvesFromAFileThatIsNotFbxIsRefusedInOneLineNamingTheFile) {
  const auto path = test::kData / "bvh/bvhio_example.bvh";
  auto read = read_source_clip(path, {});
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().find(path.string() + ": --method source replays FBX curves"), std::string::npos) << read.error();
  EXPECT_EQ(read.error().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
