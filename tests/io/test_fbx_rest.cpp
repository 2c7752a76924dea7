// The rest translations our FBX writer writes (src/io/fbx/fbx_rest.h): a joint with
// translation keys lying on its parent's +Y axis — which Blender's importer would
// connect, dropping its location keys — is moved off that axis in the rest pose
// only; every pose at every key reads back the same.
#include "fbx_rest.h"
#include "io_test_util.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

// Root → "moving" (on Root's +Y, translation keys) → "still" (on +Y, no keys).
Clip chain_with_root_motion_on_the_y_axis() {
  Clip clip;
  clip.name = "chain";
  clip.frame_time = 1.0 / 30.0;
  const char* names[] = {"Root", "moving", "still"};
  for (int j = 0; j < 3; ++j) {
    Joint joint;
    joint.name = names[j];
    joint.parent = j - 1;
    joint.offset = j == 0 ? Vec3::Zero() : Vec3(0.0, 10.0, 0.0);
    clip.skeleton.joints.push_back(joint);
    RotationTrack r;
    r.times = {0.0, 1.0 / 30.0, 2.0 / 30.0};
    r.keys = {Quat::Identity(), Quat(Eigen::AngleAxisd(0.1 * j, Vec3::UnitX())), Quat(Eigen::AngleAxisd(0.2, Vec3::UnitZ()))};
    clip.rotations.push_back(r);
    clip.translations.emplace_back();
  }
  TranslationTrack t;
  t.times = {0.0, 1.0 / 30.0, 2.0 / 30.0};
  t.keys = {Vec3(0.0, 10.0, 0.0), Vec3(0.5, 10.2, -0.3), Vec3(1.0, 10.4, -0.6)};
  clip.translations[1] = t;
  return clip;
}

TEST(FbxRest, ATranslatedJointOnItsParentsYAxisIsMovedOffItAndNoOtherIs) {
  const Clip clip = chain_with_root_motion_on_the_y_axis();
  ASSERT_TRUE(clip.validate());
  const std::vector<Vec3> rest = fbx_rest_translations(clip);
  const double reach = 20.0;  // "still" is 20 units from the origin
  EXPECT_NEAR(rest[1].x(), kFbxOffAxisShift * reach, 1e-12);
  EXPECT_EQ(rest[1].y(), 10.0);
  EXPECT_EQ(rest[0], clip.skeleton.joints[0].offset);  // a root: nothing to connect to
  EXPECT_EQ(rest[2], clip.skeleton.joints[2].offset);  // no keys to lose
}

TEST(FbxRest, MovingTheRestOffTheAxisLeavesEveryPoseAsItWas) {
  const Clip clip = chain_with_root_motion_on_the_y_axis();
  test::TempDir dir;
  ASSERT_TRUE(write_clip(clip, dir / "out.fbx"));
  const Result<Clip> back = read_clip(dir / "out.fbx");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->skeleton.joints.size(), 3u);
  for (double t : clip.rotations[0].times) {
    const WorldPose a = test::pose_at(clip, t), b = test::pose_at(*back, t);
    for (std::size_t j = 0; j < 3; ++j) {
      const auto jb = static_cast<std::size_t>(back->skeleton.find(clip.skeleton.joints[j].name));
      EXPECT_LT((a.position[j] - b.position[jb]).norm(), 1e-5) << clip.skeleton.joints[j].name << " at " << t;
    }
  }
}

}  // namespace
}  // namespace rotinterp
