// The contract for cycles, run over methods(): a periodic curve passes through its
// keys in every period, is as continuous across the seam as between keys, does not
// depend on which key starts the cycle, and is exact on a constant-velocity turn
// where the method claims exactness.
#include "support.h"

#include "rotinterp/interp/periodic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

using test::rot;

constexpr double kKeyTolerance = 1e-9;  // rad, as interpolator.h promises
// Relative jumps by finite differences: ~1e-6 (velocity) and ~1e-5 (acceleration)
// on smooth curves; a real jump is O(1) (the same limits as the contract's continuity test).
constexpr double kSmooth = 1e-4;

struct Cycle {
  RotationTrack track;  // open form
  double period;
};

// A swing in two axes with a twist, sampled at non-uniform times over one period:
// a realistic cycle whose rotation vectors stay well inside |v| < π.
Cycle swing_cycle(int n, double period) {
  Cycle c{{}, period};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int k = 0; k < n; ++k) {
    const double t = 0.7 + period * (k + (k == 0 ? 0.0 : jitter(rng))) / n;
    const double phase = 2.0 * kPi * (t - 0.7) / period;
    const Vec3 v(0.9 * std::sin(phase), 0.5 * std::cos(2.0 * phase), 0.3 * std::sin(phase + 1.0));
    c.track.times.push_back(t);
    c.track.keys.push_back(exp(RotVec(v)));
  }
  return c;
}

// The same cycle started at key s: keys s … n−1, then 0 … s−1 one period later.
Cycle rotated(const Cycle& c, std::size_t s) {
  Cycle r{{}, c.period};
  const std::size_t n = c.track.times.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (k + s) % n;
    r.track.times.push_back(c.track.times[i] + (k + s >= n ? c.period : 0.0));
    r.track.keys.push_back(c.track.keys[i]);
  }
  return r;
}

std::unique_ptr<Interpolator> build(const std::string& method, const Cycle& c) {
  auto r = make_periodic_interpolator(method, c.track, c.period);
  if (!r) {
    ADD_FAILURE() << method << ": " << r.error();
    return nullptr;
  }
  return std::move(*r);
}

// Relative velocity and acceleration jumps at time t (one-sided differences).
struct Jump {
  double velocity, acceleration;
};
Jump jump_at(const Interpolator& p, double t, double h, double vscale, double ascale) {
  const Vec3 vl = test::one_sided_velocity(p, t, -h), vr = test::one_sided_velocity(p, t, h);
  const Vec3 al = test::one_sided_acceleration(p, t, -h), ar = test::one_sided_acceleration(p, t, h);
  return {(vl - vr).norm() / vscale, (al - ar).norm() / ascale};
}

class PeriodicContract : public ::testing::TestWithParam<std::string> {
 protected:
  const MethodInfo& method() const { return *find_method(GetParam()); }
};

TEST_P(PeriodicContract, PassesThroughEveryKeyInEveryPeriod) {
  const Cycle c = swing_cycle(9, 1.3);
  auto p = build(GetParam(), c);
  ASSERT_TRUE(p);
  for (int m : {-3, -1, 0, 1, 2, 40})
    for (std::size_t k = 0; k < c.track.times.size(); ++k)
      EXPECT_LT(angular_distance(p->evaluate(c.track.times[k] + m * c.period), c.track.keys[k]), kKeyTolerance)
          << "period " << m << " key " << k;
  EXPECT_LT(angular_distance(p->evaluate(c.track.times.front() + c.period), c.track.keys.front()), kKeyTolerance);
}

TEST_P(PeriodicContract, SeamIsAsContinuousAsTheKeysInside) {
  const Cycle c = swing_cycle(11, 1.1);
  auto p = build(GetParam(), c);
  ASSERT_TRUE(p);
  const std::vector<double>& t = c.track.times;
  const double h = 2e-3 * 0.05;
  double vscale = 0.0, ascale = 0.0;
  for (double x = t.front(); x < t.front() + c.period; x += c.period / 200) {
    vscale = std::max(vscale, test::central_velocity(*p, x, 1e-5).norm());
    ascale = std::max(ascale, test::one_sided_acceleration(*p, x, 1e-3).norm());
  }
  double inside_velocity = 0.0, inside_acceleration = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const Jump j = jump_at(*p, t[k], h, vscale, ascale);
    inside_velocity = std::max(inside_velocity, j.velocity);
    inside_acceleration = std::max(inside_acceleration, j.acceleration);
  }
  for (double seam : {t.front(), t.front() + c.period, t.front() - 5 * c.period}) {
    const Jump j = jump_at(*p, seam, h, vscale, ascale);
    RecordProperty("seam_velocity_jump", std::to_string(j.velocity));
    EXPECT_LT(angular_distance(p->evaluate(seam - 1e-9), p->evaluate(seam + 1e-9)), 1e-6) << "C0 at " << seam;
    const int continuity = method().continuity;
    if (continuity >= 1) {
      EXPECT_LT(j.velocity, kSmooth) << "C1 across the seam at " << seam;
    } else {  // C⁰ methods: a corner at the seam like the corner at any key, no larger
      EXPECT_LE(j.velocity, 2.0 * inside_velocity) << "seam corner at " << seam;
    }
    if (continuity >= 2) {
      EXPECT_LT(j.acceleration, kSmooth) << "C2 across the seam at " << seam;
    }
  }
}

TEST_P(PeriodicContract, StartingTheCycleAtAnotherKeyGivesTheSameCurve) {
  const Cycle c = swing_cycle(10, 2.0);
  auto p = build(GetParam(), c);
  ASSERT_TRUE(p);
  for (std::size_t s : {1u, 4u, 9u}) {
    auto r = build(GetParam(), rotated(c, s));
    ASSERT_TRUE(r);
    double worst = 0.0;
    for (double x = -c.period; x < 2.0 * c.period; x += c.period / 333)
      worst = std::max(worst, angular_distance(p->evaluate(x), r->evaluate(x)));
    EXPECT_LT(worst, 1e-12) << "started at key " << s;
  }
}

TEST_P(PeriodicContract, ConstantVelocityFullTurnIsExactWhereClaimed) {
  if (!method().exact_on_constant_velocity) GTEST_SKIP() << "not claimed by " << GetParam();
  const Vec3 axis = Vec3(1.0, -2.0, 0.5).normalized();
  const Quat q0 = rot(Vec3(0.3, 0.2, 1.0), 0.8);
  const double period = 1.6;
  for (bool uniform : {true, false}) {
    Cycle c{{}, period};
    for (int k = 0; k < 12; ++k) {
      const double t = period * (k + (uniform || k == 0 ? 0.0 : 0.3 * std::sin(k))) / 12.0;
      c.track.times.push_back(t);
      c.track.keys.push_back(exp(RotVec(axis * (2.0 * kPi * t / period))) * q0);
    }
    auto p = build(GetParam(), c);
    ASSERT_TRUE(p);
    double worst = 0.0;
    for (double x = -period; x < 2.0 * period; x += period / 451)
      worst = std::max(worst, angular_distance(p->evaluate(x), exp(RotVec(axis * (2.0 * kPi * x / period))) * q0));
    EXPECT_LT(worst, 1e-9) << (uniform ? "uniform" : "non-uniform") << " keys";
  }
}

TEST_P(PeriodicContract, OneAndTwoKeyCyclesAndBadPeriods) {
  Cycle one{{}, 1.0};
  one.track.times = {0.2};
  one.track.keys = {rot(Vec3::UnitX(), 0.4)};
  auto p = build(GetParam(), one);
  ASSERT_TRUE(p);
  EXPECT_LT(angular_distance(p->evaluate(7.77), one.track.keys[0]), kKeyTolerance);
  Cycle two{{}, 2.0};
  two.track.times = {0.0, 1.0};
  two.track.keys = {Quat::Identity(), rot(Vec3::UnitY(), 1.0)};
  auto q = build(GetParam(), two);
  ASSERT_TRUE(q);
  EXPECT_LT(angular_distance(q->evaluate(2.0), Quat::Identity()), kKeyTolerance);
  EXPECT_TRUE(q->evaluate(std::nan("")).coeffs().allFinite());
  EXPECT_FALSE(make_periodic_interpolator(GetParam(), two.track, 1.0)) << "period not longer than the span";
  EXPECT_FALSE(make_periodic_interpolator(GetParam(), two.track, std::nan(""))) << "NaN period";
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, PeriodicContract, ::testing::ValuesIn(test::all_method_names()),
                         test::method_test_name);

}  // namespace
}  // namespace rotinterp
