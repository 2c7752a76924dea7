// clamped: the shape-preserving promises of interp/clamped.h — stops and
// reversals without overshoot, holds still, monotone progress along every arc —
// and, about one axis, exactly Steffen's monotone cubic of the angle (checked
// against the translation curve's independent scalar implementation).
#include "support.h"

#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rotinterp {
namespace {

using test::rot;
using test::Rz;

std::unique_ptr<Interpolator> clamped(const RotationTrack& t) {
  auto r = make_interpolator("clamped", t);
  EXPECT_TRUE(r) << (r ? "" : r.error());
  return r ? std::move(*r) : nullptr;
}

RotationTrack about_z(const std::vector<double>& times, const std::vector<double>& angles) {
  RotationTrack t;
  t.times = times;
  for (double a : angles) t.keys.push_back(Rz(a));
  return t;
}

TEST(Clamped, AboutOneAxisIsSteffensMonotoneCubicOfTheAngleBetweenTheEndSegments) {
  // Rising, holding, reversing, non-uniform: every case of Steffen's limiter.
  const std::vector<double> times = {0.0, 0.1, 0.35, 0.4, 0.9, 1.0, 1.6, 1.65, 2.0};
  const std::vector<double> angles = {0.0, 0.3, 1.9, 1.9, 2.2, 0.4, 0.5, 0.52, 2.5};
  auto p = clamped(about_z(times, angles));
  ASSERT_TRUE(p);
  TranslationTrack scalar;
  scalar.times = times;
  for (double a : angles) scalar.keys.push_back(Vec3(a, 0, 0));
  const TranslationCurve steffen(scalar, TranslationInterp::cubic);
  // The interior segments: the end keys take the end secant, not Steffen's parabola.
  for (int s = 0; s <= 4000; ++s) {
    const double x = times[1] + (times[times.size() - 2] - times[1]) * s / 4000;
    EXPECT_LT(angular_distance(p->evaluate(x), Rz(steffen.evaluate(x).x())), 1e-12) << x;
    EXPECT_LT((p->angular_velocity(x) - Vec3(0, 0, steffen.derivative(x).x())).norm(), 1e-9) << x;
  }
}

TEST(Clamped, AKeyWhereTheMotionStopsOrReversesHasZeroAngularVelocity) {
  const Quat a = Quat::Identity(), b = rot(Vec3(1, -2, 0.5), 1.4), c = rot(Vec3(0.2, 1, 1), 0.6);
  // Reversal at key 1 (back towards a), stop at key 3 (held into key 4).
  RotationTrack t;
  t.times = {0.0, 0.3, 0.5, 0.9, 1.4};
  t.keys = {a, b, apply_moving(b, RotVec(-0.5 * log(b).vec())), c, c};
  auto p = clamped(t);
  ASSERT_TRUE(p);
  EXPECT_LT(p->angular_velocity(0.3).norm(), 1e-12);
  EXPECT_LT(p->angular_velocity(0.9).norm(), 1e-12);
  // Near the reversal the curve never goes past key 1: its angle from a peaks there.
  const double at_key = angular_distance(a, b);
  for (int s = 0; s <= 400; ++s) EXPECT_LE(angular_distance(a, p->evaluate(0.5 * s / 400)), at_key + 1e-12);
}

TEST(Clamped, ProgressAlongEveryArcIsMonotoneAndSidewaysWithinTheDocumentedBound) {
  // Steps up to 100°, so the local rotation vector stays below π and log recovers it.
  constexpr double kSideways = 4.0 / 27.0 * (2.0 + kPi);
  double worst_side = 0.0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const RotationTrack t = test::random_track(seed, 9, 100.0 * kPi / 180.0, 0.05, 1.0);
    auto p = clamped(t);
    ASSERT_TRUE(p);
    for (std::size_t i = 0; i + 1 < t.keys.size(); ++i) {
      const Quat& qi = t.keys[i];
      const Vec3 rho = log(qi.conjugate() * t.keys[i + 1]).vec();
      const Vec3 dir = rho.normalized();
      double previous = 0.0;
      for (int s = 1; s <= 200; ++s) {
        const double x = t.times[i] + (t.times[i + 1] - t.times[i]) * s / 200.0;
        const Vec3 r = log(qi.conjugate() * p->evaluate(x)).vec();
        const double along = r.dot(dir);
        EXPECT_GE(along, previous - 1e-12) << "seed " << seed << " segment " << i << " s " << s;
        EXPECT_LE(along, rho.norm() + 1e-12) << "seed " << seed << " segment " << i;
        previous = along;
        const double side = (r - along * dir).norm() / rho.norm();
        worst_side = std::max(worst_side, side);
        EXPECT_LE(side, kSideways) << "seed " << seed << " segment " << i;
      }
    }
  }
  RecordProperty("largest_sideways_over_step", std::to_string(worst_side));
}

}  // namespace
}  // namespace rotinterp
