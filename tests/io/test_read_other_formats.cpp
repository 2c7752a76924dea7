// Formats other than BVH and FBX go through the same assimp reader; a tick rate of
// 0 ("not specified") becomes kDefaultTicksPerSecond with a warning.
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/files/file_errors.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

TEST(OtherFormats, ZeroTicksPerSecondGetsTheDefaultRateAndAWarning) {
  test::TempDir dir;
  const auto path = dir / "wave.x";
  test::write_text(path, test::zero_rate_x_scene());
  std::vector<std::string> warnings;
  ReadOptions options;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  Result<ClipFileInfo> info = inspect_clip(path, options);
  ASSERT_TRUE(info) << info.error();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], path.string() + ": animation 'Wave' gives 0 ticks per second; assuming 25");
  EXPECT_EQ(info->warnings, warnings);
  ASSERT_EQ(info->animations.size(), 1u);
  EXPECT_TRUE(info->animations[0].default_rate);
  EXPECT_DOUBLE_EQ(info->animations[0].ticks_per_second, kDefaultTicksPerSecond);

  const Clip& clip = info->clip;
  EXPECT_EQ(clip.name, "Wave");
  EXPECT_EQ(clip.source_format, "x");
  ASSERT_EQ(clip.skeleton.joints.size(), 1u);  // the identity scene root is not a joint
  EXPECT_EQ(clip.skeleton.joints[0].name, "Child");
  EXPECT_TRUE(clip.skeleton.joints[0].offset.isApprox(Vec3(0, 2, 0)));
  const RotationTrack& r = clip.rotations[0];
  ASSERT_EQ(r.times, (std::vector<double>{0.0, 10.0 / 25.0, 20.0 / 25.0}));
  EXPECT_LE(angular_distance(r.keys[1], Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()))), 1e-6);
  EXPECT_LE(angular_distance(r.keys[2], Quat(Eigen::AngleAxisd(kPi, Vec3::UnitX()))), 1e-6);
  EXPECT_GE(r.keys[2].dot(r.keys[1]), 0.0);  // sign-continuous
  EXPECT_DOUBLE_EQ(clip.frame_time, 1.0 / 25.0);  // keys on whole ticks
}

// A scene without animation is refused, naming the file.
TEST(OtherFormats, StaticSceneIsRefusedWithAClearMessage) {
  test::TempDir dir;
  const auto path = dir / "still.x";
  std::string text = test::zero_rate_x_scene();
  text = text.substr(0, text.find("AnimTicksPerSecond"));
  test::write_text(path, text);
  Result<Clip> c = read_clip(path);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error_kind(), file_error::no_animation);
  EXPECT_EQ(c.error().rfind(path.string() + ": the file has no animation (it holds ", 0), 0u) << c.error();
  // What it holds also comes as data, through the importer process.
  const ReadOutcome whole = inspect_clip_outcome(path);
  ASSERT_TRUE(whole.error);
  EXPECT_NE(whole.info.holds.find(" node"), std::string::npos) << whole.info.holds;
  EXPECT_EQ(c.error(), path.string() + ": the file has no animation (it holds " + whole.info.holds + ")");
}

}  // namespace
}  // namespace rotinterp
