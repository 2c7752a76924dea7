// Grassia's exp derivatives and swing parameterization (core/swing.h), and the
// so(3) Jacobian they meet in, checked by central finite differences.
#include "rotinterp/core/rotation.h"
#include "rotinterp/core/so3_jacobian.h"
#include "rotinterp/core/swing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace rotinterp;

namespace {

Quat reference_exp(const Vec3& v) {
  const double theta = v.norm();
  if (theta == 0.0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(theta, v / theta));
}

}  // namespace

// ---- derivatives ----------------------------------------------------------------------------

class Derivatives : public ::testing::TestWithParam<double> {};

TEST_P(Derivatives, DqDvMatchesCentralFiniteDifferences) {
  const double theta = GetParam();
  const Vec3 v = Vec3(0.6, -0.3, 0.74).normalized() * theta;
  const double h = 1e-6;
  const Eigen::Matrix<double, 4, 3> J = dq_dv(v);
  for (int i = 0; i < 3; ++i) {
    Vec3 d = Vec3::Zero();
    d[i] = h;
    const Quat p = exp(RotVec(v + d)), m = exp(RotVec(v - d));
    const Eigen::Vector4d fd((p.w() - m.w()) / (2 * h), (p.x() - m.x()) / (2 * h), (p.y() - m.y()) / (2 * h),
                             (p.z() - m.z()) / (2 * h));
    EXPECT_LT((J.col(i) - fd).norm(), 1e-9) << "theta " << theta << " column " << i;
  }
}

TEST_P(Derivatives, DRDvMatchesCentralFiniteDifferences) {
  const double theta = GetParam();
  const Vec3 v = Vec3(-0.2, 0.9, 0.4).normalized() * theta;
  const double h = 1e-6;
  const auto dR = dR_dv(v);
  for (int i = 0; i < 3; ++i) {
    Vec3 d = Vec3::Zero();
    d[i] = h;
    const Mat3 fd = (reference_exp(v + d).toRotationMatrix() - reference_exp(v - d).toRotationMatrix()) / (2 * h);
    EXPECT_LT((dR[i] - fd).norm(), 1e-8) << "theta " << theta << " index " << i;
  }
}

TEST_P(Derivatives, RotvecDerivativeMatchesFiniteDifferenceOfComposition) {
  // v(t) = log(exp(ω t)·exp(v)) on the branch through v; v̇(0) by central differences.
  const double theta = GetParam();
  const Vec3 v = Vec3(0.3, 0.5, -0.8).normalized() * theta;
  const Vec3 omega(0.7, -1.1, 0.4);
  const double h = 1e-6;
  const Vec3 plus = log_nearest(exp(RotVec(omega * h)) * exp(RotVec(v)), RotVec(v)).vec();
  const Vec3 minus = log_nearest(exp(RotVec(-omega * h)) * exp(RotVec(v)), RotVec(v)).vec();
  const Vec3 fd = (plus - minus) / (2 * h);
  EXPECT_LT((so3_left_jacobian_inverse_times(v, omega) - fd).norm(), 1e-7 * std::max(1.0, fd.norm())) << "theta " << theta;
}

INSTANTIATE_TEST_SUITE_P(Angles, Derivatives,
                         ::testing::Values(0.0, 1e-9, 1e-6, 1e-4, 5e-3, 0.0099, 0.0101, 0.5, 2.0, 3.1, 3.2, 4.5,
                                           kTwoPi - 0.05, kTwoPi + 0.05));

TEST(Rotation, SmallAngleEtaHasTheSignOfTheGeneralFormula) {
  // Grassia's η = (ω·v/θ)(cot(θ/2) − 2/θ); its limit is −(ω·v)(60 + θ²)/360, not +.
  const Vec3 omega(0.3, -0.2, 0.9);
  for (double theta : {0.05, 0.1, 0.2}) {
    const Vec3 v = Vec3(1, 1, 1).normalized() * theta;
    const double eta = omega.dot(v) / theta * (1.0 / std::tan(theta / 2) - 2.0 / theta);
    const double series = -omega.dot(v) * (60.0 + theta * theta) / 360.0;
    EXPECT_NEAR(eta, series, 1e-5 * std::abs(eta));
    EXPECT_GT(std::abs(eta + series), std::abs(eta));  // the printed sign is the wrong one
  }
}

// ---- swing parameterization ---------------------------------------------------------------

TEST(Rotation, SwingParameterizationChainRuleMatchesFiniteDifferences) {
  const SwingParam p = SwingParam::perpendicular_to(Vec3(0.2, 0.1, 1.0));
  EXPECT_NEAR(p.s.dot(p.t), 0.0, 1e-15);
  EXPECT_NEAR(p.s.dot(Vec3(0.2, 0.1, 1.0).normalized()), 0.0, 1e-15);
  for (auto [a, b] : {std::pair{0.0, 0.0}, {0.3, -0.2}, {1.5, 2.0}, {1e-7, 1e-8}}) {
    const auto J = p.dq_dswing(a, b);
    const double h = 1e-6;
    const Eigen::Vector4d da = (p.orientation(a + h, b).coeffs() - p.orientation(a - h, b).coeffs()) / (2 * h);
    const Eigen::Vector4d db = (p.orientation(a, b + h).coeffs() - p.orientation(a, b - h).coeffs()) / (2 * h);
    // coeffs() is (x, y, z, w); J rows are (w, x, y, z).
    const Eigen::Vector4d ja(J(1, 0), J(2, 0), J(3, 0), J(0, 0)), jb(J(1, 1), J(2, 1), J(3, 1), J(0, 1));
    EXPECT_LT((ja - da).norm(), 1e-9);
    EXPECT_LT((jb - db).norm(), 1e-9);
  }
}

TEST(Rotation, SwingLimitIsTheEllipse) {
  const double a = 0.8, b = 0.3;
  for (int k = 0; k < 360; ++k) {
    const double phi = k * kPi / 180.0;
    EXPECT_TRUE(within_swing_limit(0.999 * a * std::cos(phi), 0.999 * b * std::sin(phi), a, b));
    EXPECT_FALSE(within_swing_limit(1.001 * a * std::cos(phi), 1.001 * b * std::sin(phi), a, b));
  }
  EXPECT_FALSE(within_swing_limit(0.0, 0.0, 0.0, 1.0));  // degenerate limits admit nothing
}
