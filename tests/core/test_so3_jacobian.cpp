// The SO(3) Jacobians (so3_jacobian.h) against their definitions by perturbation,
// with central finite differences of the core exp and log (manif's conventions):
//   J_l(v)δ ≈ log(exp(v + δ)·exp(v)⁻¹)      J_r(v)δ ≈ log(exp(v)⁻¹·exp(v + δ))
//   J_l⁻¹(v)δ ≈ log(exp(δ)·exp(v)) − v      J_r⁻¹(v)δ ≈ log(exp(v)·exp(δ)) − v
// at angles from 0 to just below π, over many random directions.
#include "rotinterp/core/so3_jacobian.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace rotinterp;

namespace {

// Every test's angles: zero, tiny, both sides of each series switch, large, and
// next to π.
const std::vector<double> kAngles = {0.0,   1e-9,  1e-4, 1e-2 * (1 - 1e-9), 1e-2, 1e-2 * (1 + 1e-9), 0.1,
                                     0.249, 0.251, 0.5,  1.0,               3.0,  kPi - 1e-6};
constexpr int kDirections = 200;
constexpr double kStep = 1e-6;  // central differences: error ~kStep² + ε/kStep ≈ 1e-10

// A direction uniform on the sphere (rejection from the cube).
Vec3 direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    const Vec3 d(u(rng), u(rng), u(rng));
    if (d.squaredNorm() > 1e-4 && d.squaredNorm() <= 1.0) return d.normalized();
  }
}

// log(q) − v on the branch through v (log_nearest), so that θ near π does not jump to −v.
Vec3 log_minus(const Quat& q, const Vec3& v) {
  const RotVec branch(v);
  const Vec3 near = log_nearest(q, branch).vec();
  return near - v;
}

// Column i of the matrix whose product with δ is f(δ), f odd to first order:
// (f(h·eᵢ) − f(−h·eᵢ))/2h.
Mat3 central_differences(const std::function<Vec3(const Vec3&)>& f) {
  Mat3 m;
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = kStep * Vec3::Unit(i);
    m.col(i) = (f(d) - f(-d)) / (2 * kStep);
  }
  return m;
}

// Checks `jacobian(v)` against the finite differences of `perturbation(v, ·)` for
// every angle and direction; also its product form against the matrix.
void expect_matches_perturbation(const std::function<Mat3(const Vec3&)>& jacobian,
                                 const std::function<Vec3(const Vec3&, const Vec3&)>& times,
                                 const std::function<Vec3(const Vec3&, const Vec3&)>& perturbation,
                                 unsigned seed) {
  std::mt19937_64 rng(seed);
  for (double theta : kAngles) {
    for (int k = 0; k < kDirections; ++k) {
      const Vec3 v = direction(rng) * theta;
      const Mat3 J = jacobian(v);
      const Mat3 fd = central_differences([&](const Vec3& d) { return perturbation(v, d); });
      ASSERT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-8) << "theta " << theta << " v " << v.transpose();
      const Vec3 x = direction(rng);
      ASSERT_LT((times(v, x) - J * x).norm(), 1e-14) << "theta " << theta;
    }
  }
}

}  // namespace

TEST(So3Jacobian, LeftJacobianIsThePerturbationOfExpOnTheLeft) {
  expect_matches_perturbation(
      so3_left_jacobian, so3_left_jacobian_times,
      [](const Vec3& v, const Vec3& d) { return log(exp(RotVec(v + d)) * exp(RotVec(v)).conjugate()).vec(); }, 1);
}

TEST(So3Jacobian, RightJacobianIsThePerturbationOfExpOnTheRight) {
  expect_matches_perturbation(
      so3_right_jacobian, so3_right_jacobian_times,
      [](const Vec3& v, const Vec3& d) { return log(exp(RotVec(v)).conjugate() * exp(RotVec(v + d))).vec(); }, 2);
}

TEST(So3Jacobian, LeftJacobianInverseIsThePerturbationOfLogOnTheLeft) {
  expect_matches_perturbation(
      so3_left_jacobian_inverse, so3_left_jacobian_inverse_times,
      [](const Vec3& v, const Vec3& d) { return log_minus(exp(RotVec(d)) * exp(RotVec(v)), v); },
      3);
}

TEST(So3Jacobian, RightJacobianInverseIsThePerturbationOfLogOnTheRight) {
  expect_matches_perturbation(
      so3_right_jacobian_inverse, so3_right_jacobian_inverse_times,
      [](const Vec3& v, const Vec3& d) { return log_minus(exp(RotVec(v)) * exp(RotVec(d)), v); },
      4);
}

// d/dt (J(r + t·u)·u) at t = 0, by central differences of the (tested) Jacobian.
void expect_rate_matches(const std::function<Mat3(const Vec3&)>& jacobian,
                         const std::function<Vec3(const Vec3&, const Vec3&)>& rate, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(0.1, 3.0);
  for (double theta : kAngles) {
    for (int k = 0; k < kDirections; ++k) {
      const Vec3 r = direction(rng) * theta;
      const Vec3 u = direction(rng) * speed(rng);
      const Vec3 fd = (jacobian(r + kStep * u) * u - jacobian(r - kStep * u) * u) / (2 * kStep);
      ASSERT_LT((rate(r, u) - fd).norm(), 1e-8 * (1.0 + fd.norm())) << "theta " << theta;
    }
  }
}

TEST(So3Jacobian, RightJacobianRateIsTheDerivativeAlongTheMotion) {
  expect_rate_matches(so3_right_jacobian, so3_right_jacobian_rate, 5);
}

TEST(So3Jacobian, LeftJacobianRateIsTheDerivativeAlongTheMotion) {
  expect_rate_matches(so3_left_jacobian, so3_left_jacobian_rate, 6);
}

TEST(So3Jacobian, InverseTimesForwardIsTheIdentity) {
  std::mt19937_64 rng(7);
  for (double theta : kAngles) {
    for (int k = 0; k < kDirections; ++k) {
      const Vec3 v = direction(rng) * theta;
      // Round-off grows with the entries of J⁻¹ (~θ²/π² … π²/4 below π).
      const double tol = 1e-14 * (1.0 + theta * theta);
      EXPECT_LT((so3_left_jacobian_inverse(v) * so3_left_jacobian(v) - Mat3::Identity()).norm(), tol);
      EXPECT_LT((so3_right_jacobian_inverse(v) * so3_right_jacobian(v) - Mat3::Identity()).norm(), tol);
      // J_r = J_lᵀ (and so for the inverses).
      EXPECT_LT((so3_right_jacobian(v) - so3_left_jacobian(v).transpose()).norm(), 1e-15);
    }
  }
}

TEST(So3Jacobian, AtZeroEveryJacobianIsTheIdentityAndEveryRateZero) {
  const Vec3 zero = Vec3::Zero(), u(0.3, -1.2, 0.7);
  for (const Mat3& J : {so3_left_jacobian(zero), so3_right_jacobian(zero), so3_left_jacobian_inverse(zero),
                        so3_right_jacobian_inverse(zero)})
    EXPECT_EQ(J, Mat3::Identity());
  EXPECT_EQ(so3_right_jacobian_rate(zero, u), Vec3::Zero());
  EXPECT_EQ(so3_left_jacobian_rate(zero, u), Vec3::Zero());
}

// Each coefficient is continuous across its series switch: the series and the
// closed form agree there to the accuracy the header states.
TEST(So3Jacobian, CoefficientsAreContinuousAcrossTheirSeriesSwitch) {
  auto gap = [](double (*f)(double), double at) {
    const double below = f(at * (1 - 1e-12)), above = f(at * (1 + 1e-12));
    return std::abs(below - above) / std::abs(above);
  };
  EXPECT_LT(gap(so3_jacobian_b, kSo3JacobianSeries), 1e-13);  // the closed form's 6ε/θ²
  EXPECT_LT(gap(so3_jacobian_da, kSo3JacobianSeries), 1e-11);  // the closed form's 60ε/θ⁴
  EXPECT_LT(gap(so3_jacobian_db, kSo3JacobianSeries), 1e-11);
  EXPECT_LT(gap(so3_jacobian_c, kSo3JacobianInverseSeries), 1e-10);  // the closed form's 12ε/θ²
  EXPECT_EQ(so3_jacobian_a(0.0), 0.5);
  EXPECT_NEAR(so3_jacobian_a(1e-9), 0.5, 1e-17);
}

TEST(So3Jacobian, InverseProductOfNonFiniteInputIsZero) {
  const double nan = std::nan(""), inf = HUGE_VAL;
  for (const Vec3& v : {Vec3(nan, 0, 0), Vec3(inf, 0, 0), Vec3(1e200, 1e200, 0)}) {
    EXPECT_EQ(so3_left_jacobian_inverse_times(v, Vec3(1, 2, 3)), Vec3::Zero());
    EXPECT_EQ(so3_right_jacobian_inverse_times(v, Vec3(1, 2, 3)), Vec3::Zero());
  }
  EXPECT_EQ(so3_left_jacobian_inverse_times(Vec3(0.1, 0.2, 0.3), Vec3(nan, 0, 0)), Vec3::Zero());
}

// The Newton iteration's coarser c: within its stated truncation θ⁶/1209600 of c
// (relative 12·θ⁶/1209600 plus round-off); so3_left_jacobian_inverse_with.
TEST(So3Jacobian, NewtonCoefficientIsCWithinItsTruncation) {
  for (double theta : kAngles) {
    const double c = so3_jacobian_c(theta), coarse = so3_jacobian_c_newton(theta * theta);
    const double t6 = std::pow(theta, 6);
    // … plus the closed form's own 12ε/θ² where c uses it.
    const double closed = theta >= kSo3JacobianInverseSeries ? 12.0 * 2.3e-16 / (theta * theta) : 0.0;
    EXPECT_LE(std::abs(coarse - c) / c, 12.0 * t6 / 1209600.0 * 1.01 + closed + 1e-14) << "theta " << theta;
  }
  const Vec3 v(0.2, -0.4, 0.1);
  EXPECT_EQ(so3_left_jacobian_inverse_with(v, so3_jacobian_c(v.norm())), so3_left_jacobian_inverse(v));
}
