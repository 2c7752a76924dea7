// reduce's selection (reduce/reduce.h) on synthetic chains and a real clip: two keys
// where slerp is exact, fitted values through jitter, holds, a zero-like budget, the
// shell budget catching drift down a chain, and per-joint budgets; each measured with
// the eval metrics, not the selection's own code.
#include "reduce_measure.h"

#include "rotinterp/clip/synth.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

using test::max_of;
using test::measure;
using test::Measured;
using test::Motion;

const std::string kCmu = std::string(ROTINTERP_SHARED_DATA) + "/bvh/cmu_01_01.bvh";

constexpr double kDeg = kPi / 180.0;

// ---- properties of the selection -----------------------------------------------------

// A chain of `joints` joints along +y, bones `bone` long, each with the motion `make(j)`.
SynthMotion chain(std::size_t joints, double bone, const std::function<JointMotion(std::size_t)>& make) {
  Skeleton sk;
  std::vector<JointMotion> motion;
  for (std::size_t j = 0; j < joints; ++j) {
    Joint joint;
    joint.name = "j" + std::to_string(j);
    joint.parent = static_cast<int>(j) - 1;
    joint.offset = j == 0 ? Vec3::Zero() : Vec3(0, bone, 0);
    sk.joints.push_back(joint);
    motion.push_back(make(j));
  }
  EndSite end;
  end.parent = static_cast<int>(joints) - 1;
  end.offset = Vec3(0, bone, 0);
  sk.end_sites.push_back(end);
  return SynthMotion(sk, motion);
}

TEST(Reduce, SlerpKeepsTwoKeysPerJointOnConstantAngularVelocity) {
  const SynthMotion motion = chain(4, 30, [](std::size_t j) {
    JointMotion m;
    VectorCurve c;
    c.c1 = Vec3(0.2 + 0.05 * double(j), -0.1, 0.25);  // rad/s about a fixed axis: constant ω, < 90° in 4 s
    m.factors.push_back(c);
    m.base = exp(RotVec(0.2 * double(j), 0.1, -0.3));
    return m;
  });
  const Clip clip = motion.sample(4.0, Rate{30, 1}, "constant");
  ReduceOptions o;
  o.method = "slerp";
  o.budget.rotation_deg = 1e-6;
  o.budget.shell = 1e-6;
  o.shell_distance = 10;
  auto r = reduce_clip(clip, o);
  ASSERT_TRUE(r) << r.error();
  for (const ReducedJoint& j : r->joints) {
    EXPECT_EQ(j.rotation_frames, (std::vector<std::size_t>{0, 120}));
    EXPECT_LE(j.max_rotation_error, 1e-6 * kDeg);
  }
}

// Keys are not bound to the source's values: a steady turn with ±0.55 of the budget
// of jitter frame to frame at 120 Hz (capture noise) keeps every frame when keys copy
// the source (the chord between two keys of one sign misses the frame between them
// by 1.1 budgets), but a few keys near the middle of the jitter hold every frame:
// new keys start from the source smoothed over ±1 frame, and removals refit their
// neighbours.
TEST(Reduce, FittedKeyValuesRideOutJitterThatSourceValuedKeysWouldHaveToKeepFrameByFrame) {
  const SynthMotion motion = chain(1, 30, [](std::size_t) {
    JointMotion m;
    VectorCurve c;
    c.c1 = Vec3(0.3, -0.1, 0.2);
    m.factors.push_back(c);
    return m;
  });
  Clip clip = motion.sample(1.0, Rate{120, 1}, "jitter");
  const double budget_deg = 0.5;
  RotationTrack& track = clip.rotations[0];
  for (std::size_t f = 0; f < track.keys.size(); ++f)
    track.keys[f] = track.keys[f] * exp(RotVec(0, 0, (f % 2 ? -0.55 : 0.55) * budget_deg * kDeg));
  const std::size_t frames = track.keys.size();
  for (const MethodInfo& method : methods()) {
    ReduceOptions o;
    o.method = method.name;
    o.budget.rotation_deg = budget_deg;
    auto r = reduce_clip(clip, o);
    ASSERT_TRUE(r) << method.name << ": " << r.error();
    EXPECT_LE(r->kept_keys, frames / 10) << method.name << " of " << frames;
    // Every frame, rebuilt from the result's own keys, within the budget.
    std::vector<Quat> q(frames);
    (*make_interpolator(method.name, r->reduced.rotations[0]))->evaluate(track.times.data(), frames, q.data());
    double worst = 0.0;
    for (std::size_t f = 0; f < frames; ++f) worst = std::max(worst, angular_distance(track.keys[f], q[f]));
    EXPECT_LE(worst, budget_deg * kDeg * (1 + 1e-9)) << method.name;
  }
}

TEST(Reduce, AHoldCostsAtMostItsTwoEnds) {
  // Moves for 1 s, holds still from frame 30 to frame 90, moves again.
  const SynthMotion moving = chain(3, 20, [](std::size_t j) {
    JointMotion m;
    VectorCurve c;
    c.waves.push_back({Vec3(0.6, 0.2 + 0.1 * double(j), -0.4), 2.3, 0.3});
    c.waves.push_back({Vec3(-0.1, 0.3, 0.2), 5.1, 1.0});
    m.factors.push_back(c);
    return m;
  });
  Clip clip = moving.sample(4.0, Rate{30, 1}, "hold");
  for (RotationTrack& t : clip.rotations)
    for (std::size_t f = 31; f <= 90; ++f) t.keys[f] = t.keys[30];
  for (const MethodInfo& method : methods()) {
    if (!method.preserves_holds) continue;
    ReduceOptions o;
    o.method = method.name;
    o.budget.rotation_deg = 0.01;
    auto r = reduce_clip(clip, o);
    ASSERT_TRUE(r) << r.error();
    for (const ReducedJoint& j : r->joints) {
      for (std::size_t f : j.rotation_frames) EXPECT_TRUE(f <= 30 || f >= 90) << method.name << " keeps frame " << f << " inside the hold";
      EXPECT_LE(j.max_rotation_error, 0.01 * kDeg * (1 + 1e-9));
    }
  }
}

TEST(Reduce, KeysAreNeverMoreThanTheSourcesAndEveryFrameIsKeptForAZeroLikeBudget) {
  const SynthMotion motion = chain(2, 10, [](std::size_t) {
    JointMotion m;
    VectorCurve c;
    c.waves.push_back({Vec3(1.0, 0.5, -0.4), 9.0, 0.3});
    m.factors.push_back(c);
    return m;
  });
  const Clip clip = motion.sample(1.0, Rate{30, 1}, "tight");
  ReduceOptions o;
  o.method = "squad";
  o.budget.rotation_deg = 1e-12;
  auto r = reduce_clip(clip, o);
  ASSERT_TRUE(r) << r.error();
  for (const ReducedJoint& j : r->joints) EXPECT_LE(j.rotation_frames.size(), 31u);
  EXPECT_LE(r->kept_keys, r->source_keys);
}

// Per-joint budgets each pass, yet the hand drifts: errors of one sign add up
// down the chain. The shell budget, measured with the ancestors' rebuilt motion,
// catches it.
TEST(Reduce, AHandDriftingBeyondTheShellBudgetIsCaughtThoughEveryJointIsWithinItsOwn) {
  const SynthMotion motion = chain(5, 30, [](std::size_t) {
    JointMotion m;
    VectorCurve c;
    c.waves.push_back({Vec3(0, 0, 0.5), 3.0, 0.0});  // every joint bends the same way
    c.waves.push_back({Vec3(0, 0, 0.1), 11.0, 0.5});
    m.factors.push_back(c);
    return m;
  });
  const Clip clip = motion.sample(3.0, Rate{60, 1}, "arm");
  const DenseClip ref = exact_dense_clip(clip);
  auto rebuilt = [&](const ReduceResult& r) {
    Motion m{ref.rotation, ref.translation};
    for (std::size_t j = 0; j < r.joints.size(); ++j)
      (*make_interpolator("slerp", r.reduced.rotations[j]))->evaluate(ref.grid.times.data(), ref.grid.size(), m.rotation[j].data());
    return m;
  };
  const double shell_distance = 10, shell_budget = 0.1;  // 1 mm at 10 cm in centimetres
  ReduceOptions local;
  local.method = "slerp";
  local.budget.rotation_deg = 0.5;
  auto per_joint = reduce_clip(clip, local);
  ASSERT_TRUE(per_joint) << per_joint.error();
  const Measured loose = measure(clip, ref, rebuilt(*per_joint), shell_distance);
  EXPECT_LE(max_of(loose.angle), 0.5 * kDeg * (1 + 1e-9));
  EXPECT_GT(loose.shell.back(), 3 * shell_budget) << "the fixture should drift at the hand";

  ReduceOptions hierarchical = local;
  hierarchical.budget.shell = shell_budget;
  hierarchical.shell_distance = shell_distance;
  auto held = reduce_clip(clip, hierarchical);
  ASSERT_TRUE(held) << held.error();
  const Measured tight = measure(clip, ref, rebuilt(*held), shell_distance);
  EXPECT_LE(max_of(tight.angle), 0.5 * kDeg * (1 + 1e-9));
  for (std::size_t j = 0; j < tight.shell.size(); ++j) EXPECT_LE(tight.shell[j], shell_budget * (1 + 1e-9)) << j;
  EXPECT_LE(held->joints.back().max_shell_error, shell_budget * (1 + 1e-9));
}

TEST(Reduce, APerJointBudgetTightensThatJointOnly) {
  auto source = read_clip(kCmu);
  ASSERT_TRUE(source) << source.error();
  ReduceOptions o;
  o.budget.rotation_deg = 2;
  o.budget.translation = 1;
  o.budget_for.emplace_back("LeftHand", ReduceBudget{0.05, 0, 0});
  auto r = reduce_clip(*source, o);
  ASSERT_TRUE(r) << r.error();
  const auto hand = static_cast<std::size_t>(source->skeleton.find("LeftHand"));
  EXPECT_LE(r->joints[hand].max_rotation_error, 0.05 * kDeg * (1 + 1e-9));
  EXPECT_DOUBLE_EQ(r->joints[hand].budget.rotation_deg, 0.05);
  const auto other = static_cast<std::size_t>(source->skeleton.find("RightHand"));
  EXPECT_DOUBLE_EQ(r->joints[other].budget.rotation_deg, 2);
  o.budget_for.emplace_back("NoSuchJoint", ReduceBudget{1, 0, 0});
  auto bad = reduce_clip(*source, o);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("NoSuchJoint"), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
