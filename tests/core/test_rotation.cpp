// Properties of the rotation core, checked against independent references:
// Eigen's AngleAxis, central finite differences, closed forms.
#include "rotinterp/core/rotation.h"
#include "rotinterp/core/so3_jacobian.h"
#include "rotinterp/core/swing.h"

#include "support/random_rotations.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace rotinterp;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using test::random_quat;
using test::random_unit;

// Same orientation (q ≡ −q) within tol.
double orientation_gap(const Quat& a, const Quat& b) { return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm()); }

Quat reference_exp(const Vec3& v) {
  const double theta = v.norm();
  if (theta == 0.0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(theta, v / theta));
}

bool finite(const Quat& q) { return q.coeffs().allFinite(); }

}  // namespace

// ---- exp / log -------------------------------------------------------------------------

TEST(Rotation, ExpMatchesAngleAxis) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> angle(0.0, 3.0 * kPi);
  for (int i = 0; i < 10000; ++i) {
    const Vec3 v = random_unit(rng) * angle(rng);
    EXPECT_LT((exp(RotVec(v)).coeffs() - reference_exp(v).coeffs()).norm(), 4 * kEps) << v.transpose();
  }
}

TEST(Rotation, LogInvertsExpToTwelveDigitsOverHundredThousandVectors) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> uniform(0.0, kPi);
  std::uniform_real_distribution<double> decade(-12.0, -3.0);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    double theta;
    switch (i % 4) {
      case 0: theta = std::pow(10.0, decade(rng)); break;  // 1e-12 … 1e-3
      case 1: theta = kPi - std::pow(10.0, -9.0 + 6.0 * uniform(rng) / kPi); break;  // up to π − 1e-9
      default: theta = uniform(rng);
    }
    const Vec3 v = random_unit(rng) * theta;
    const Vec3 back = log(exp(RotVec(v))).vec();
    const double rel = (back - v).norm() / v.norm();
    worst = std::max(worst, rel);
    ASSERT_LT(rel, 1e-12) << "theta " << theta;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(Rotation, ExpIsContinuousAcrossTheTaylorThreshold) {
  // With the paper's misprinted 1/2 + θ²/48 the two sides would differ by ~θ³/24 ≈ 7e-14.
  const Vec3 axis = Vec3(1.0, -2.0, 0.5).normalized();
  const double t = kExpTaylorThreshold;
  const Quat below = exp(RotVec(axis * (t * (1.0 - 1e-12))));
  const Quat above = exp(RotVec(axis * (t * (1.0 + 1e-12))));
  EXPECT_LT((below.coeffs() - above.coeffs()).norm(), 4 * kEps);
  EXPECT_LT((below.coeffs() - reference_exp(axis * t).coeffs()).norm(), 4 * kEps);
}

TEST(Rotation, ExpSeriesBranchMatchesAngleAxisAndIsContinuousAtItsThreshold) {
  // Angles spread over the series branch (log-uniform down to 1e-9 and uniform up to
  // the threshold): the nested series against Eigen's AngleAxis (libm sin/cos).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, kExpSeriesThreshold);
  std::uniform_real_distribution<double> decade(-9.0, std::log10(kExpSeriesThreshold));
  for (int i = 0; i < 200000; ++i) {
    const double theta = i % 2 ? uniform(rng) : std::pow(10.0, decade(rng));
    const Vec3 v = random_unit(rng) * theta;
    ASSERT_LT((exp(RotVec(v)).coeffs() - reference_exp(v).coeffs()).norm(), 4 * kEps) << theta;
  }
  const Vec3 axis = Vec3(-0.2, 0.7, 1.0).normalized();
  const double t = kExpSeriesThreshold;
  const Quat below = exp(RotVec(axis * std::nextafter(t, 0.0)));
  const Quat above = exp(RotVec(axis * t));
  EXPECT_LT((below.coeffs() - above.coeffs()).norm(), 4 * kEps);
}

TEST(Rotation, HalfAngleIsWithinTwoUlpOfLibmAtan2) {
  // The series branch (s ≤ w/8), its edge, the libm branch, and the special values.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> ratio(0.0, 0.125), wide(0.0, 10.0), w_dist(1e-3, 1e3);
  std::uniform_real_distribution<double> decade(-300.0, 0.0);
  for (int i = 0; i < 1000000; ++i) {
    const double w = w_dist(rng);
    double s;
    switch (i % 4) {
      case 0: s = ratio(rng) * w; break;
      case 1: s = std::pow(10.0, decade(rng)) * w; break;
      case 2: s = std::nextafter(0.125 * w, i % 8 < 4 ? 0.0 : 1.0); break;
      default: s = wide(rng) * w;
    }
    const double expected = std::atan2(s, w), got = half_angle(s, w);
    ASSERT_LE(std::abs(got - expected), 2.0 * kEps * expected) << "s " << s << " w " << w;
  }
  for (double w : {1.0, 0.0, -0.0, -1.0, std::numeric_limits<double>::denorm_min()})
    for (double s : {0.0, 1e-300, 0.5, 1.0, std::numeric_limits<double>::infinity()})
      EXPECT_EQ(half_angle(s, w), std::atan2(s, w)) << s << ", " << w;
  EXPECT_TRUE(std::isnan(half_angle(std::nan(""), 1.0)));
  EXPECT_TRUE(std::isnan(half_angle(0.1, std::nan(""))));
}

TEST(Rotation, LogIsExactNearIdentity) {
  for (double theta : {1e-300, 1e-200, 1e-30, 1e-16, 1e-12, 1e-8}) {
    const Vec3 v = Vec3(0.3, -0.4, 1.2).normalized() * theta;
    EXPECT_LT((log(exp(RotVec(v))).vec() - v).norm(), 2 * kEps * theta) << theta;
  }
}

TEST(Rotation, LogAtExactly180DegreesIsTheSameForQAndMinusQ) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a = random_unit(rng);
    const Quat q(0.0, a.x(), a.y(), a.z());
    const Quat mq(-0.0, -a.x(), -a.y(), -a.z());
    const RotVec v = log(q), w = log(mq);
    EXPECT_EQ(v.vec(), w.vec());
    EXPECT_NEAR(v.angle(), kPi, 1e-15);
    EXPECT_LT(orientation_gap(exp(v), q), 1e-15);
  }
  // A key that is half a turn about x: the axis points along +x.
  EXPECT_GT(log(Quat(0, -1, 0, 0)).x(), 0.0);
}

TEST(Rotation, NoNanOnHardFixtures) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Quat> quats = {Quat(1, 0, 0, 0),   Quat(-1, 0, 0, 0),      Quat(0, 1, 0, 0),
                                   Quat(0, 0, 0, -1),  Quat(0, 0, 0, 0),       Quat(1e-300, 0, 0, 0),
                                   Quat(1e300, 1e300, 0, 0), Quat(nan, 0, 0, 0), Quat(inf, 1, 0, 0),
                                   Quat(2, 0, 0, 0),   Quat(1, 1e-300, 0, 0)};
  for (const Quat& a : quats) {
    EXPECT_TRUE(log(a).vec().allFinite());
    EXPECT_TRUE(finite(exp(log(a))));
    EXPECT_TRUE(log_nearest(a, RotVec(7, 0, 0)).vec().allFinite());
    for (const Quat& b : quats) {
      EXPECT_TRUE(std::isfinite(angular_distance(a, b)));
      EXPECT_TRUE(displacement_fixed(a, b).vec().allFinite());
      EXPECT_TRUE(displacement_moving(a, b).vec().allFinite());
      EXPECT_TRUE(angular_velocity(a, b, 0.01).allFinite());
    }
  }
  for (const Vec3& v : {Vec3(nan, 0, 0), Vec3(inf, 0, 0), Vec3(1e200, 1e200, 0), Vec3(0, 0, 0)}) {
    EXPECT_TRUE(finite(exp(RotVec(v))));
    EXPECT_NEAR(exp(RotVec(v)).norm(), 1.0, 1e-15);
    EXPECT_TRUE(dq_dv(v).allFinite());
    EXPECT_TRUE(so3_left_jacobian_inverse_times(v, Vec3(1, 2, 3)).allFinite());
  }
  // Antipodal keys are the same orientation: distance 0, displacement 0.
  const Quat q = Quat(0.5, 0.5, -0.5, 0.5);
  const Quat mq(-q.w(), -q.x(), -q.y(), -q.z());
  EXPECT_EQ(angular_distance(q, mq), 0.0);
  EXPECT_LT(displacement_fixed(q, mq).angle(), 1e-15);
}

TEST(Rotation, NonUnitInputIsNormalized) {
  const Quat q = exp(RotVec(0.3, 0.2, -0.1));
  const Quat scaled(q.coeffs() * 7.5);
  EXPECT_LT((log(scaled).vec() - log(q).vec()).norm(), 1e-15);
  EXPECT_NEAR(normalized_or_identity(scaled).norm(), 1.0, 1e-15);
}

// ---- nearest-branch log, reparameterization ------------------------------------------------

TEST(Rotation, NearestBranchLogFollowsThreeFullTurnsWithoutJumps) {
  const Vec3 omega = Vec3(0.2, -0.7, 0.4).normalized() * 2.5;  // rad/s
  const double dt = 0.05;
  RotVec prev;
  const int steps = static_cast<int>(3.0 * kTwoPi / (omega.norm() * dt)) + 10;
  for (int k = 1; k <= steps; ++k) {
    const Vec3 exact = omega * (k * dt);
    const RotVec v = log_nearest(exp(RotVec(exact)), prev);
    ASSERT_LT((v.vec() - exact).norm(), 1e-12 * std::max(1.0, exact.norm())) << "step " << k;
    ASSERT_LT((v.vec() - prev.vec()).norm(), omega.norm() * dt * (1 + 1e-9));
    prev = v;
  }
  EXPECT_GT(prev.angle(), 3.0 * kTwoPi);
}

TEST(Rotation, NearestBranchLogOfIdentityPicksTheNearestShell) {
  const Vec3 p = Vec3(1, 2, 2) / 3.0 * (kTwoPi + 0.3);
  EXPECT_LT((log_nearest(Quat::Identity(), RotVec(p)).vec() - p.normalized() * kTwoPi).norm(), 1e-14);
  EXPECT_EQ(log_nearest(Quat::Identity(), RotVec(0.1, 0, 0)).angle(), 0.0);
}

TEST(Rotation, NearestBranchLogIsAPreimage) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> big(0.0, 20.0);
  for (int i = 0; i < 10000; ++i) {
    const Quat q = random_quat(rng);
    const RotVec prev(random_unit(rng) * big(rng));
    const RotVec v = log_nearest(q, prev);
    EXPECT_LT(orientation_gap(exp(v), q), 1e-12);
    // No other candidate on its line is nearer.
    const Vec3 axis = v.vec().normalized();
    for (double k : {-1.0, 1.0})
      EXPECT_LE((v.vec() - prev.vec()).norm(), (v.vec() + k * kTwoPi * axis - prev.vec()).norm() + 1e-12);
  }
}

TEST(Rotation, ReparameterizeKeepsTheRotationAndShortensIt) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(kPi + 1e-9, kTwoPi - 1e-9);
  for (int i = 0; i < 1000; ++i) {
    const RotVec v(random_unit(rng) * angle(rng));
    const RotVec r = reparameterize(v);
    EXPECT_LE(r.angle(), kPi);
    EXPECT_LT(orientation_gap(exp(r), exp(v)), 1e-14);
  }
  const RotVec small(0.1, 0.2, 0.3);
  EXPECT_EQ(reparameterize(small).vec(), small.vec());
}

// ---- angular velocity ---------------------------------------------------------------------

TEST(Rotation, AngularVelocityIntegratesBack) {
  std::mt19937_64 rng(6);
  for (int i = 0; i < 1000; ++i) {
    const Quat q0 = random_quat(rng), q1 = random_quat(rng);
    const double dt = 0.01 + i * 1e-3;
    const Vec3 w = angular_velocity(q0, q1, dt);
    EXPECT_LE(w.norm() * dt, kPi + 1e-12);
    EXPECT_LT(orientation_gap(integrate_angular_velocity(q0, w, dt), q1), 1e-12);
  }
  EXPECT_EQ(angular_velocity(Quat::Identity(), Quat(0, 1, 0, 0), 0.0), Vec3::Zero());
}

// ---- Lee's operations and distance ----------------------------------------------------------

TEST(Rotation, ComposeMatchesQuaternionProduct) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.0, kPi);
  for (int i = 0; i < 1000; ++i) {
    const RotVec a(random_unit(rng) * angle(rng)), b(random_unit(rng) * angle(rng));
    EXPECT_LT(orientation_gap(exp(compose(a, b)), exp(a) * exp(b)), 1e-14);
  }
}

TEST(Rotation, DisplacementsAreCoordinateInvariantAsLeeStates) {
  std::mt19937_64 rng(8);
  for (int i = 0; i < 1000; ++i) {
    const Quat q = random_quat(rng), q2 = random_quat(rng), R = random_quat(rng), S = random_quat(rng);
    // Moving-frame displacement ignores a change of world frame (left multiplication).
    EXPECT_LT((displacement_moving(R * q, R * q2).vec() - displacement_moving(q, q2).vec()).norm(), 1e-12);
    // Fixed-frame displacement ignores a change of body frame (right multiplication) …
    EXPECT_LT((displacement_fixed(q * S, q2 * S).vec() - displacement_fixed(q, q2).vec()).norm(), 1e-12);
    // … and rotates with a change of world frame.
    EXPECT_LT((displacement_fixed(R * q, R * q2).vec() - R * displacement_fixed(q, q2).vec()).norm(), 1e-12);
    // Applying the displacement on its side reaches q2.
    EXPECT_LT(orientation_gap(apply_fixed(displacement_fixed(q, q2), q), q2), 1e-14);
    EXPECT_LT(orientation_gap(apply_moving(q, displacement_moving(q, q2)), q2), 1e-14);
    // Distance is bi-invariant.
    EXPECT_NEAR(angular_distance(R * q * S, R * q2 * S), angular_distance(q, q2), 1e-12);
  }
}

TEST(Rotation, AngularDistanceIsAccurateForTinyAnglesAndFloatNoise) {
  const Quat q = exp(RotVec(0.4, -1.0, 0.7));
  for (double eps : {1e-12, 1e-9, 1e-6, 1e-3}) {
    const Quat q2 = apply_moving(q, RotVec(Vec3(0.2, 0.3, -0.9).normalized() * eps));
    // Limited by how well q2 itself is stored (~ε per coefficient), not by the formula.
    EXPECT_NEAR(angular_distance(q, q2), eps, std::max(1e-6 * eps, 4 * kEps)) << eps;
  }
  // The same orientation stored in floats reads as float noise, well below 1e-4°.
  const Quat qf = q.cast<float>().cast<double>();
  EXPECT_LT(angular_distance(q, qf) * 180.0 / kPi, 1e-4);
  // Matches Eigen where Eigen is accurate.
  std::mt19937_64 rng(9);
  for (int i = 0; i < 1000; ++i) {
    const Quat a = random_quat(rng), b = random_quat(rng);
    EXPECT_NEAR(angular_distance(a, b), a.angularDistance(b), 1e-7);
  }
}

TEST(Rotation, HatAndVeeAreInverseAndHatIsTheCrossProduct) {
  const Vec3 a(0.3, -1.2, 2.0), b(-0.7, 0.1, 0.5);
  EXPECT_LT((hat(a) * b - a.cross(b)).norm(), 1e-15);
  EXPECT_EQ(vee(hat(a)), a);
}

// ---- swing / twist ----------------------------------------------------------------------------

TEST(Rotation, SwingTwistRecomposesWithTwistAboutTheAxis) {
  std::mt19937_64 rng(10);
  for (int i = 0; i < 1000; ++i) {
    const Quat q = random_quat(rng);
    const Vec3 axis = random_unit(rng);
    const SwingTwist st = swing_twist(q, axis);
    EXPECT_LT(orientation_gap(st.swing * st.twist, q), 1e-14);
    EXPECT_LT(st.twist.vec().cross(axis).norm(), 1e-14);  // twist axis ∥ axis
    EXPECT_LT(std::abs(st.swing.vec().dot(axis)), 1e-14);  // swing axis ⟂ axis
  }
}

TEST(Rotation, PureTwistAndPureSwingSeparate) {
  const Vec3 axis = Vec3(0, 1, 0);
  const SwingTwist twist_only = swing_twist(exp(RotVec(axis * 0.8)), axis);
  EXPECT_NEAR(angular_distance(twist_only.swing, Quat::Identity()), 0.0, 1e-15);
  EXPECT_NEAR(angular_distance(twist_only.twist, Quat::Identity()), 0.8, 1e-14);
  const SwingTwist swing_only = swing_twist(exp(RotVec(Vec3(0.6, 0, 0.8) * 1.1)), axis);
  EXPECT_NEAR(angular_distance(swing_only.twist, Quat::Identity()), 0.0, 1e-15);
  EXPECT_NEAR(angular_distance(swing_only.swing, Quat::Identity()), 1.1, 1e-14);
  // A 180° swing: twist is the identity, no NaN.
  const SwingTwist half = swing_twist(Quat(0, 1, 0, 0), axis);
  EXPECT_TRUE(finite(half.swing) && finite(half.twist));
  EXPECT_LT(orientation_gap(half.swing * half.twist, Quat(0, 1, 0, 0)), 1e-15);
}
