// The cycle check: which form a clip's cycle takes, which joints miss closure, and
// that a root may advance every cycle but not rise.
#include "cycle_clips.h"

#include "rotinterp/clip/loop.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

using test::cycle_clip;
using test::CycleTruth;

constexpr double kDeg = kPi / 180.0;

TEST(CycleCheck, FindsTheClosedAndTheOpenFormOfASyntheticCycle) {
  const CycleTruth truth{4.0 / 3.0, Vec3(1.2, 0.0, 0.0)};
  for (LoopForm form : {LoopForm::closed, LoopForm::open}) {
    auto c = check_loop(cycle_clip(truth, 40, form));
    ASSERT_TRUE(c) << c.error();
    EXPECT_TRUE(c->looks_like_cycle) << loop_check_text(*c);
    EXPECT_EQ(c->form, form) << loop_check_text(*c);
    EXPECT_EQ(c->period_frames, 40u);
    EXPECT_NEAR(c->period, truth.period, 1e-12);
    EXPECT_TRUE(c->misses.empty());
    EXPECT_NEAR(c->root_advance.x(), 1.2, form == LoopForm::closed ? 1e-12 : 0.02) << "forward motion per cycle";
    EXPECT_LT(c->root_vertical_offset, 0.01);
  }
}

TEST(CycleCheck, ForcedFormIsKeptAndTheOtherMisses) {
  const CycleTruth truth{4.0 / 3.0, Vec3::Zero()};
  auto c = check_loop(cycle_clip(truth, 40, LoopForm::closed), LoopForm::open);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->form, LoopForm::open);
  EXPECT_FALSE(c->misses.empty()) << "a closed cycle read as open misses by one step";
  EXPECT_FALSE(c->looks_like_cycle);
}

TEST(CycleCheck, ReportsAJointThatMissesClosureByItsAngle) {
  const CycleTruth truth{1.0, Vec3::Zero()};
  Clip clip = cycle_clip(truth, 30, LoopForm::closed);
  clip.rotations[2].keys.back() = exp(RotVec(Vec3(0.0, 0.0, 4.4 * kDeg))) * clip.rotations[2].keys.back();
  auto c = check_loop(clip);
  ASSERT_TRUE(c);
  ASSERT_EQ(c->misses.size(), 1u);
  EXPECT_EQ(c->misses[0].name, "swing");
  EXPECT_NEAR(c->misses[0].angle, 4.4 * kDeg, 1e-9);
  EXPECT_NE(loop_check_text(*c).find("swing 4.40°"), std::string::npos) << loop_check_text(*c);
}

TEST(CycleCheck, ARootThatRisesEveryCycleIsNotACycle) {
  Clip clip = cycle_clip(CycleTruth{1.0, Vec3::Zero()}, 30, LoopForm::closed);
  clip.translations[0]->keys.back().y() += 0.05;  // 5 cm higher at the end
  auto c = check_loop(clip);
  ASSERT_TRUE(c);
  EXPECT_FALSE(c->looks_like_cycle);
  EXPECT_NEAR(c->root_vertical_offset, 0.05, 1e-12);
}

TEST(CycleCheck, AStillClipIsNotACycle) {
  Clip clip = cycle_clip(CycleTruth{1.0, Vec3::Zero()}, 30, LoopForm::closed);
  for (RotationTrack& r : clip.rotations)
    for (Quat& q : r.keys) q = Quat::Identity();
  auto c = check_loop(clip);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->moving_joints, 0u);
  EXPECT_FALSE(c->looks_like_cycle);
}

TEST(CycleCheck, TheLineCountsEachJointOnceAsClosingOrMissing) {
  Clip clip = cycle_clip(CycleTruth{1.0, Vec3::Zero()}, 30, LoopForm::closed);
  clip.rotations[2].keys.back() = exp(RotVec(Vec3(0.0, 0.0, 77.0 * kDeg))) * clip.rotations[2].keys.back();
  auto c = check_loop(clip, LoopForm::closed);
  ASSERT_TRUE(c);
  const std::string text = loop_check_text(*c);
  EXPECT_NE(text.find("; 2 joints close within"), std::string::npos) << text;
  EXPECT_NE(text.find("1 joint misses closure"), std::string::npos) << text;
  EXPECT_EQ(text.find("; joints close within"), std::string::npos) << "not all joints close: " << text;
}

TEST(CycleCheck, ABoxSlidingAlongTheGroundTranslatesAndDoesNotRise) {
  // One joint (no extent: no tallest axis), still, its root 15 m further along X each cycle.
  Clip clip;
  clip.name = "box";
  clip.skeleton.joints = {{"box", -1, Vec3::Zero(), Quat::Identity()}};
  clip.frame_time = 1.0 / 30.0;
  clip.unit.metres_per_unit = 1.0;
  clip.rotations.resize(1);
  clip.translations.resize(1);
  TranslationTrack root;
  for (int k = 0; k <= 30; ++k) {
    const double t = k / 30.0;
    clip.rotations[0].times.push_back(t);
    clip.rotations[0].keys.push_back(Quat::Identity());
    root.times.push_back(t);
    root.keys.push_back(Vec3(15.0 * t, 0.0, 0.0));
  }
  clip.translations[0] = root;
  auto c = check_loop(clip, LoopForm::closed);
  ASSERT_TRUE(c);
  const std::string text = loop_check_text(*c);
  EXPECT_EQ(c->root_vertical_offset, 0.0) << text;
  EXPECT_NE(text.find("root translates 15 m per cycle"), std::string::npos) << text;
  EXPECT_EQ(text.find("rises"), std::string::npos) << text;
  EXPECT_EQ(text.find("nothing moves"), std::string::npos) << "the root moves: " << text;
}

TEST(CycleCheck, ParsesTheLoopWords) {
  EXPECT_FALSE(parse_loop_form("auto")->has_value());
  EXPECT_EQ(**parse_loop_form("closed"), LoopForm::closed);
  EXPECT_EQ(**parse_loop_form("open"), LoopForm::open);
  EXPECT_FALSE(parse_loop_form("wrap"));
}

}  // namespace
}  // namespace rotinterp
