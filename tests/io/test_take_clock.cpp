// One clock for every take (issue 44): a take spans its stack's LocalStart..LocalStop
// where it declares one, else its keys; frame 0 is its start; frames are placed at
// the file's own rate. Fixtures are ASCII FBX written here: three takes on one
// shared timeline whose curves hold every key of it, as 3ds Max and MotionBuilder
// export them, and keys off the frame grid.
#include "fbx_legacy.h"
#include "io_test_util.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/io/fbx_source.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

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

constexpr long long kFrameTicks = 1539538600;  // 1/30 s
constexpr double kDegreesPerRadian = 180.0 / kPi;

struct TakeSpec {
  std::string name;
  int first_frame, last_frame;  // LocalStart, LocalStop; equal: none declared
};

// One bone whose T and R curves are given per frame time (seconds) at `key_times`;
// each take has its own layer, curve nodes and curves, all holding the same keys.
std::string fbx_text(const std::vector<TakeSpec>& takes, const std::vector<double>& key_times,
                     const std::function<double(int channel, double t)>& value, bool state_rate) {
  std::string objects = "\tModel: 1000, \"Model::Bone\", \"LimbNode\" {\n\t\tVersion: 232\n\t}\n";
  std::string links = "\tC: \"OO\",1000,0\n";
  long long id = 2000;
  std::string times;
  for (double t : key_times) times += (times.empty() ? "" : ",") + std::to_string(std::llround(t * 30.0 * kFrameTicks));
  for (const TakeSpec& take : takes) {
    const long long stack = id++, layer = id++;
    std::string span;
    if (take.first_frame != take.last_frame)
      span = "\t\tProperties70:  {\n\t\t\tP: \"LocalStart\", \"KTime\", \"Time\", \"\"," +
             std::to_string(take.first_frame * kFrameTicks) + "\n\t\t\tP: \"LocalStop\", \"KTime\", \"Time\", \"\"," +
             std::to_string(take.last_frame * kFrameTicks) + "\n\t\t}\n";
    objects += "\tAnimationStack: " + std::to_string(stack) + ", \"AnimStack::" + take.name + "\", \"\" {\n" + span + "\t}\n";
    objects += "\tAnimationLayer: " + std::to_string(layer) + ", \"AnimLayer::Base\", \"\" {\n\t}\n";
    links += "\tC: \"OO\"," + std::to_string(layer) + "," + std::to_string(stack) + "\n";
    for (int property = 0; property < 2; ++property) {
      const long long node = id++;
      objects += "\tAnimationCurveNode: " + std::to_string(node) + ", \"AnimCurveNode::" + (property ? "R" : "T") +
                 "\", \"\" {\n\t}\n";
      links += "\tC: \"OO\"," + std::to_string(node) + "," + std::to_string(layer) + "\n";
      links += "\tC: \"OP\"," + std::to_string(node) + ",1000, \"" + (property ? "Lcl Rotation" : "Lcl Translation") + "\"\n";
      for (int axis = 0; axis < 3; ++axis) {
        const long long curve = id++;
        std::string values;
        for (double t : key_times) values += (values.empty() ? "" : ",") + std::to_string(value(3 * property + axis, t));
        const std::string n = std::to_string(key_times.size());
        objects += "\tAnimationCurve: " + std::to_string(curve) + ", \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4009\n" +
                   "\t\tKeyTime: *" + n + " {\n\t\t\ta: " + times + "\n\t\t}\n\t\tKeyValueFloat: *" + n +
                   " {\n\t\t\ta: " + values + "\n\t\t}\n\t}\n";
        links += "\tC: \"OP\"," + std::to_string(curve) + "," + std::to_string(node) + ", \"d|" + "XYZ"[axis] + "\"\n";
      }
    }
  }
  const std::string settings = state_rate ? "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
                                            "\t\tP: \"TimeMode\", \"enum\", \"\", \"\",6\n\t}\n}\n"
                                          : "";
  return "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n" +
         settings + "Objects:  {\n" + objects + "}\nConnections:  {\n" + links + "}\n";
}

// A move along X over 0–0.667 s, along Y over 0.833–1.333 s, a 180° spin about Z
// over 1.5–2 s (holding between), keyed at every frame of the 2 s timeline.
double shared_timeline_value(int channel, double t) {
  const auto ramp = [](double t, double a, double b) { return std::clamp((t - a) / (b - a), 0.0, 1.0); };
  if (channel == 0) return 10.0 * ramp(t, 0.0, 20.0 / 30);
  if (channel == 1) return 10.0 * ramp(t, 25.0 / 30, 40.0 / 30);
  if (channel == 5) return 180.0 * ramp(t, 45.0 / 30, 2.0);
  return 0.0;
}

std::vector<double> every_frame(int last) {
  std::vector<double> t;
  for (int f = 0; f <= last; ++f) t.push_back(f / 30.0);
  return t;
}

class TakeClock : public ::testing::Test {
 protected:
  test::TempDir dir_;
  std::string write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    test::write_text(path, text);
    return path.string();
  }
};

double angle_degrees(const Quat& a, const Quat& b) { return angular_distance(a, b) * kDegreesPerRadian; }
double z_degrees(const Quat& q) { return 2.0 * std::atan2(q.z(), q.w()) * kDegreesPerRadian; }

TEST_F(TakeClock, EachTakeOfASharedTimelineIsItsOwnSpanAtTheFilesRate) {
  const std::string path = write("shared.fbx", fbx_text({{"anim 1", 0, 20}, {"anim 2", 25, 40}, {"spin", 45, 60}},
                                                       every_frame(60), shared_timeline_value, true));
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
  const std::string path = write("shared.fbx", fbx_text({{"anim 1", 0, 20}, {"anim 2", 25, 40}, {"spin", 45, 60}},
                                                       every_frame(60), shared_timeline_value, true));
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
  const std::string path = write("shared.fbx", fbx_text({{"anim 1", 0, 20}, {"anim 2", 25, 40}, {"spin", 45, 60}},
                                                       every_frame(60), shared_timeline_value, true));
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
  const std::string path = write("shared.fbx", fbx_text({{"anim 1", 0, 20}, {"anim 2", 25, 40}, {"spin", 45, 60}},
                                                       every_frame(60), shared_timeline_value, true));
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
