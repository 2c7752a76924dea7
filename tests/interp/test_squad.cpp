// squad against glm, on the Rz(0, .3, .6, .9) keys, and on non-uniform times.
#include "support.h"

#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/slerp.h"
#include "rotinterp/interp/squad.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace rotinterp {
namespace {

using test::Rz;

glm::dquat to_glm(const Quat& q) { return glm::dquat(q.w(), q.x(), q.y(), q.z()); }
Quat from_glm(const glm::dquat& q) { return Quat(q.w, q.x, q.y, q.z); }

std::unique_ptr<Interpolator> squad_of(const RotationTrack& t) {
  auto r = make_interpolator("squad", t);
  EXPECT_TRUE(r) << (r ? "" : r.error());
  return r ? std::move(*r) : nullptr;
}

// Largest angle between our squad and glm's (squad + intermediate) on the interior
// segments of uniformly spaced, sign-aligned keys (glm has no end-key convention).
double worst_against_glm(RotationTrack t, int samples_per_segment) {
  t.make_sign_continuous();
  auto p = squad_of(t);
  if (!p) return kPi;
  std::vector<glm::dquat> g;
  for (const Quat& q : t.keys) g.push_back(to_glm(q));
  double worst = 0.0;
  for (std::size_t i = 1; i + 2 < t.keys.size(); ++i) {
    const glm::dquat s0 = glm::intermediate(g[i - 1], g[i], g[i + 1]);
    const glm::dquat s1 = glm::intermediate(g[i], g[i + 1], g[i + 2]);
    for (int k = 0; k <= samples_per_segment; ++k) {
      const double h = static_cast<double>(k) / samples_per_segment;
      const Quat ref = from_glm(glm::squad(g[i], g[i + 1], s0, s1, h));
      worst = std::max(worst, angular_distance(p->evaluate(t.times[i] + h * (t.times[i + 1] - t.times[i])), ref));
    }
  }
  return worst;
}

TEST(Squad, MatchesGlmSquadAndIntermediateOnUniformSignAlignedKeys) {
  EXPECT_LT(worst_against_glm(test::random_track(3, 10, 0.9, 0.5, 0.5), 20), 1e-9);
}

TEST(Squad, MatchesGlmsNonFlippingSquadOnKeySteps90To179Point9Degrees) {
  // glm::squad blends with glm::mix, the great-arc slerp as stored: Shoemake's
  // curve. A shortest-arc blend differs from it (by up to 180°) wherever the dot
  // of the blended points turns negative mid-segment.
  std::uniform_real_distribution<double> step(kPi / 2, 179.9 * kPi / 180);
  const RotationTrack t = test::random_walk_track(
      23, 12, [&](std::mt19937_64& rng) { return step(rng); }, [](std::mt19937_64&) { return 0.5; });
  EXPECT_LT(worst_against_glm(t, 200), 1e-9);
}

TEST(Squad, GivesExactlyRzOnKeysRz0_3_6_9AsGlmDoesWithCtorInit) {
  RotationTrack t;
  t.times = {0, 1, 2, 3};
  t.keys = {Rz(0.0), Rz(0.3), Rz(0.6), Rz(0.9)};
  auto p = squad_of(t);
  ASSERT_TRUE(p);
  for (int k = 0; k <= 300; ++k) {
    const double x = 3.0 * k / 300;
    EXPECT_LT(angular_distance(p->evaluate(x), Rz(0.3 * x)), 1e-15) << x;  // end segments too
  }
  // glm on the interior segment, built with GLM_FORCE_CTOR_INIT (see tests/CMakeLists.txt).
  std::vector<glm::dquat> g;
  for (const Quat& q : t.keys) g.push_back(to_glm(q));
  const glm::dquat s1 = glm::intermediate(g[0], g[1], g[2]);
  const glm::dquat s2 = glm::intermediate(g[1], g[2], g[3]);
  for (int k = 0; k <= 10; ++k) {
    const double h = k / 10.0;
    EXPECT_LT(angular_distance(from_glm(glm::squad(g[1], g[2], s1, s2, h)), Rz(0.3 + 0.3 * h)), 1e-12) << h;
  }
}

// Velocity jump across the key at t (relative to |ω|), by one-sided differences.
double velocity_jump(const Interpolator& p, double t, double h) {
  const Vec3 l = test::one_sided_velocity(p, t, -h), r = test::one_sided_velocity(p, t, h);
  return (l - r).norm() / std::max(l.norm(), r.norm());
}

// The textbook control points sᵢ (uniform-time formula) on the same keys.
class TextbookSquad final : public Interpolator {
 public:
  explicit TextbookSquad(RotationTrack t) : t_(std::move(t)) {
    const std::size_t n = t_.keys.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Quat& q = t_.keys[i];
      const Quat prev = i > 0 ? t_.keys[i - 1] : q * t_.keys[1].conjugate() * q;
      const Quat next = i + 1 < n ? t_.keys[i + 1] : q * t_.keys[n - 2].conjugate() * q;
      s_.push_back(apply_moving(q, RotVec(-0.25 * (log(q.conjugate() * next) + log(q.conjugate() * prev)).vec())));
    }
  }
  Quat evaluate(double x) const override {
    std::size_t i = 0;
    while (i + 2 < t_.times.size() && x >= t_.times[i + 1]) ++i;
    const double h = std::clamp((x - t_.times[i]) / (t_.times[i + 1] - t_.times[i]), 0.0, 1.0);
    return squad(t_.keys[i], t_.keys[i + 1], s_[i], s_[i + 1], h);
  }

 private:
  RotationTrack t_;
  std::vector<Quat> s_;
};

TEST(Squad, IsC1AcrossNonUniformKeysAt0_1_1p1_3WhereTheTextbookFormulaIsNot) {
  RotationTrack t = test::random_track(5, 4, 0.8, 1.0, 1.0);
  t.times = {0, 1, 1.1, 3};
  auto p = squad_of(t);
  ASSERT_TRUE(p);
  const TextbookSquad textbook(t);
  for (std::size_t k : {1u, 2u}) {
    EXPECT_LT(velocity_jump(*p, t.times[k], 1e-5), 1e-6) << "key " << k;
    const double naive = velocity_jump(textbook, t.times[k], 1e-5);
    EXPECT_GT(naive, 0.05) << "key " << k;
    std::printf("[ info ] key %zu at t=%.1f: textbook squad velocity jump %.0f%%\n", k, t.times[k], 100 * naive);
  }
}

TEST(Squad, IsExactOnConstantAngularVelocityAtTimes0_1_1p1_3) {
  const Vec3 omega(0.4, -1.1, 0.7);
  const Quat q0 = test::random_quat(*std::make_unique<std::mt19937_64>(8));
  auto p = squad_of(test::constant_velocity_track(omega, q0, {0, 1, 1.1, 3}));
  ASSERT_TRUE(p);
  for (int k = 0; k <= 300; ++k) {
    const double x = 3.0 * k / 300;
    EXPECT_LT(angular_distance(p->evaluate(x), integrate_angular_velocity(q0, omega, x)), 1e-14) << x;
  }
}

}  // namespace
}  // namespace rotinterp
