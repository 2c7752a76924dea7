// clip/rebuild.h: the one rebuild eval measures and render draws, checked against
// what it must be computed independently: the keys themselves at key frames, a
// hand-computed slerp halfway between two keys, the frame error's joint rule, and
// the keys of a cycle.
#include "rotinterp/clip/rebuild.h"

#include "cycle_clips.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rotinterp;

namespace {

constexpr double kDeg = 180.0 / kPi;

// Joint "turn" turns about z by angle(k) at frame k; joint "still" has one key.
// Key times of "turn" are `jitter` of a frame off the grid, alternately early and
// late, as float32 times of long clips are.
Clip turning_clip(std::size_t frames, double (*angle)(std::size_t), double jitter = 0.0) {
  Clip clip;
  clip.frame_time = 1.0 / 30.0;
  clip.unit.metres_per_unit = 1.0;
  clip.skeleton.joints = {Joint{"turn", -1, Vec3::Zero(), Quat::Identity()},
                          Joint{"still", 0, Vec3(0, 1, 0), Quat::Identity()}};
  clip.rotations.resize(2);
  clip.translations.resize(2);
  for (std::size_t k = 0; k < frames; ++k) {
    const double off = k == 0 || k + 1 == frames ? 0.0 : (k % 2 ? jitter : -jitter);
    clip.rotations[0].times.push_back((static_cast<double>(k) + off) * clip.frame_time);
    clip.rotations[0].keys.push_back(Quat(Eigen::AngleAxisd(angle(k), Vec3::UnitZ())));
  }
  clip.rotations[1] = RotationTrack{{0.0}, {Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))}};
  return clip;
}

double accelerating(std::size_t k) { return 0.02 * static_cast<double>(k * k); }

std::vector<std::string> every_method() {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods()) names.push_back(m.name);
  return names;
}

TEST(Rebuild, EveryMethodGivesTheKeysBackAtKeyFramesAndErrsBetweenThem) {
  const Clip clip = turning_clip(41, accelerating, 1e-3);
  auto rebuilt = RebuiltClip::build(clip, every_method(), 4);
  ASSERT_TRUE(rebuilt) << rebuilt.error();
  EXPECT_EQ(rebuilt->keys(), (std::vector<std::size_t>{0, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40}));
  std::vector<Quat> local;
  for (std::size_t m = 0; m < methods().size(); ++m) {
    SCOPED_TRACE(methods()[m].name);
    double between = 0.0;
    for (std::size_t f = 0; f < rebuilt->frames(); ++f) {
      const FrameError e = rebuilt->method_rotations(m, f, local);
      if (f % 4 == 0) {
        EXPECT_LT(e.max, 1e-9) << "frame " << f;
        // The source's key at that frame, whose time is off the grid.
        EXPECT_LT(angular_distance(local[0], clip.rotations[0].keys[f]) * kDeg, 1e-9) << "frame " << f;
      } else {
        between = std::max(between, e.max);
      }
    }
    EXPECT_GT(between, 0.01);  // an accelerating turn is no method's exact case
  }
}

TEST(Rebuild, SlerpHalfwayBetweenTwoKeysIsTheTurnByTheirMeanAngle) {
  // Keys at frames 0 and 2 (angles 0 and 0.08 rad about z): slerp at frame 1 turns
  // by 0.04 rad, where the source turned by 0.02 rad, an error of 0.02 rad.
  const Clip clip = turning_clip(3, accelerating);
  auto rebuilt = RebuiltClip::build(clip, {"slerp"}, 2);
  ASSERT_TRUE(rebuilt) << rebuilt.error();
  const Quat want(Eigen::AngleAxisd(0.04, Vec3::UnitZ()));
  EXPECT_LT(angular_distance(rebuilt->method_rotation(0, 0, 1), want), 1e-14);
  std::vector<Quat> local;
  std::vector<double> joint_error;
  int worst = -2;
  const FrameError e = rebuilt->method_rotations(0, 1, local, &joint_error, &worst);
  EXPECT_NEAR(joint_error[0], 0.02 * kDeg, 1e-9);
  EXPECT_EQ(worst, 0);
  // Only "turn" is animated: the still joint is not counted in the frame's mean.
  EXPECT_NEAR(e.mean, 0.02 * kDeg, 1e-9);
  EXPECT_NEAR(e.max, 0.02 * kDeg, 1e-9);
}

TEST(Rebuild, AStillJointStaysItsOneKeyAndCountsOnlyWhenNoJointMoves) {
  Clip clip = turning_clip(9, accelerating);
  auto rebuilt = RebuiltClip::build(clip, every_method(), 4);
  ASSERT_TRUE(rebuilt) << rebuilt.error();
  std::vector<Quat> local;
  std::vector<double> joint_error;
  for (std::size_t m = 0; m < methods().size(); ++m)
    for (std::size_t f = 0; f < rebuilt->frames(); ++f) {
      (void)rebuilt->method_rotations(m, f, local, &joint_error);
      EXPECT_LT(angular_distance(local[1], clip.rotations[1].keys[0]) * kDeg, 1e-9) << methods()[m].name << " " << f;
    }
  // Nothing moves: every joint counts, and the rebuilt pose is the clip's.
  clip.rotations[0] = RotationTrack{{0.0}, {Quat::Identity()}};
  clip.rotations[1].times = {0.0};
  auto still = RebuiltClip::build(clip, {"slerp"}, 4);
  ASSERT_TRUE(still) << still.error();
  int worst = -2;
  const FrameError e = still->method_rotations(0, 0, local, nullptr, &worst);
  EXPECT_EQ(worst, 0);
  EXPECT_LT(e.max, 1e-9);
}

TEST(Rebuild, ACycleKeepsThePeriodsKeysAndWrapsToFrameZeroOnePeriodOn) {
  const test::CycleTruth truth{1.0, Vec3(0.5, 0.0, 0.0)};
  const Clip clip = test::cycle_clip(truth, 24, LoopForm::closed);
  auto cycle = cycle_frames(clip, LoopForm::closed);
  ASSERT_TRUE(cycle) << cycle.error();
  const DenseClip dense = dense_clip(clip);
  const std::vector<double>& times = dense.grid.times;
  // The closed form's last frame (t₀ + P) is frame 0 again: a key, as the wrap.
  EXPECT_EQ(key_frames(times, 5, &*cycle), (std::vector<std::size_t>{0, 5, 10, 15, 20, 24}));
  EXPECT_EQ(key_frames(times, 5, nullptr), (std::vector<std::size_t>{0, 5, 10, 15, 20, 24}));
  EXPECT_EQ(key_frames(times, 4, &*cycle), (std::vector<std::size_t>{0, 4, 8, 12, 16, 20, 24}));
  // Spacing 4 reaches frame 24, t₀ + P: the periodic curve's keys stop before it.
  auto by_four = rebuild_joint(times, dense.rotation[1], "c2", 4, &*cycle, 1);
  ASSERT_TRUE(by_four) << by_four.error();
  EXPECT_EQ(by_four->keys.times.size(), 6u);
  for (const char* method : {"slerp", "c2", "bf"}) {
    SCOPED_TRACE(method);
    auto spin = rebuild_joint(times, dense.rotation[1], method, 5, &*cycle, 1);
    ASSERT_TRUE(spin) << spin.error();
    EXPECT_TRUE(spin->periodic);
    EXPECT_EQ(spin->keys.times.size(), 5u);  // 0, 5, 10, 15, 20: frame 24 is frame 0 of the next period
    ASSERT_EQ(spin->jump_times.size(), 6u);
    EXPECT_DOUBLE_EQ(spin->jump_times.back(), times.front() + truth.period);
    // Played in a loop: the curve one period on is the curve at the start.
    EXPECT_LT(angular_distance(spin->curve->evaluate(times.front() + truth.period), dense.rotation[1][0]), 1e-12);
    // Without the cycle: the ordinary curve through every 5th frame and the last.
    auto plain = rebuild_joint(times, dense.rotation[1], method, 5, nullptr, 1);
    ASSERT_TRUE(plain) << plain.error();
    EXPECT_FALSE(plain->periodic);
    EXPECT_EQ(plain->keys.times.size(), 6u);
  }
  // A joint that misses closure keeps its ordinary curve.
  CycleFrames missed = *cycle;
  missed.looped[1] = false;
  auto popped = rebuild_joint(times, dense.rotation[1], "c2", 5, &missed, 1);
  ASSERT_TRUE(popped) << popped.error();
  EXPECT_FALSE(popped->periodic);
  EXPECT_EQ(popped->keys.times.size(), 6u);
}

TEST(Rebuild, AClipThatIsNoCycleIsRefusedWhenTheFormIsDetected) {
  const Clip clip = turning_clip(30, accelerating);
  auto cycle = cycle_frames(clip, std::nullopt);
  ASSERT_FALSE(cycle);
  EXPECT_EQ(cycle.error().rfind("--loop: the clip does not look like a cycle", 0), 0u) << cycle.error();
}

}  // namespace
