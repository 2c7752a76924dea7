// SO(3) Jacobians of the exponential map, in manif's names and conventions (Solà,
// Deray, Atchuthan, "A micro Lie theory for state estimation in robotics", 2018,
// eqs. 143–146; manif's SO3Tangent::ljac, rjac, ljacinv, rjacinv):
//   exp(v + δ) ≈ exp(J_l(v)·δ)·exp(v) ≈ exp(v)·exp(J_r(v)·δ)   for small δ,
//   J_l(v) = I + a(θ)[v]× + b(θ)[v]×²,     J_r(v) = J_l(−v) = J_l(v)ᵀ,
//   J_l⁻¹(v) = I − ½[v]× + c(θ)[v]×²,      J_r⁻¹(v) = J_l⁻¹(−v),
// θ = |v|, a = (1 − cos θ)/θ², b = (θ − sin θ)/θ³, c = (1 − (θ/2)cot(θ/2))/θ².
// With the rotation core's conventions (rotation.h): for q(t) = exp(v(t)) the
// fixed-frame angular velocity is ω = J_l(v)·v̇ and the body one ω_b = J_r(v)·v̇;
// conversely v̇ = J_l⁻¹(v)·ω (Grassia's v̇ = ω − ½v×ω + c·v×(v×ω); he writes c as
// η = −2c(ω·v), whose small-angle limit is −(ω·v)(60 + θ²)/360 — the paper's η₀
// has the opposite sign). J_l⁻¹ and J_r⁻¹ are singular at θ = 2π: reparameterize()
// first.
//
// Every coefficient is computed in one place below, each with one small-angle
// switch to its Taylor series and the reason for it (c also in a coarser form for
// the Buss–Fillmore average's Newton iteration, whose outputs depend on it).
#pragma once

#include "rotinterp/core/rotation.h"

#include <cmath>

namespace rotinterp {

// ---- coefficients (θ ≥ 0) ----------------------------------------------------------

// a(θ) = (1 − cos θ)/θ² = ½(sin(θ/2)/(θ/2))²: no cancellation in this form, so no
// series (only θ = 0 needs its limit ½).
inline double so3_jacobian_a(double theta) {
  if (theta == 0.0) return 0.5;
  const double h = 0.5 * theta;
  const double s = std::sin(h) / h;
  return 0.5 * s * s;
}

// Below this angle (rad) b, a′/θ and b′/θ use their series through θ⁸: the first
// omitted term is below 2e-15 relative there, while the closed forms cancel,
// losing 6ε/θ² (b: 2e-14 at 0.25) up to 60ε/θ⁴ (b′/θ: 3e-12 at 0.25).
constexpr double kSo3JacobianSeries = 0.25;

// b(θ) = (θ − sin θ)/θ³.
inline double so3_jacobian_b(double theta) {
  const double t2 = theta * theta;
  if (theta < kSo3JacobianSeries)
    return 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362880.0 + t2 * t2 * t2 * t2 / 39916800.0;
  return (theta - std::sin(theta)) / (t2 * theta);
}

// a′(θ)/θ, the rate of a along θ̇ = (v·v̇)/θ.
inline double so3_jacobian_da(double theta) {
  const double t2 = theta * theta;
  if (theta < kSo3JacobianSeries)
    return -1.0 / 12.0 + t2 / 180.0 - t2 * t2 / 6720.0 + t2 * t2 * t2 / 453600.0 - t2 * t2 * t2 * t2 / 47900160.0;
  const double omc = 2.0 * std::sin(0.5 * theta) * std::sin(0.5 * theta);
  return (theta * std::sin(theta) - 2.0 * omc) / (t2 * t2);
}

// b′(θ)/θ.
inline double so3_jacobian_db(double theta) {
  const double t2 = theta * theta;
  if (theta < kSo3JacobianSeries)
    return -1.0 / 60.0 + t2 / 1260.0 - t2 * t2 / 60480.0 + t2 * t2 * t2 / 4989600.0 -
           t2 * t2 * t2 * t2 / 622702080.0;
  const double omc = 2.0 * std::sin(0.5 * theta) * std::sin(0.5 * theta);
  return (theta * omc - 3.0 * (theta - std::sin(theta))) / (t2 * t2 * theta);
}

// Below this angle (rad) c uses its series 1/12 + θ²/720 + θ⁴/30240: the closed
// form cancels, losing about 12ε/θ² relatively (3e-11 at 1e-2), while the series'
// truncation, θ⁶/1209600, is below 1e-17 relative there.
constexpr double kSo3JacobianInverseSeries = 1e-2;

// c(θ) = (1 − (θ/2)cot(θ/2))/θ², the J_l⁻¹ coefficient.
inline double so3_jacobian_c(double theta) {
  if (theta < kSo3JacobianInverseSeries) {
    const double t2 = theta * theta;
    return 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  }
  const double half = 0.5 * theta;
  return (1.0 - half * std::cos(half) / std::sin(half)) / (theta * theta);
}

// c from θ² with its three series terms up to θ = 0.5 (θ² < 0.25): no square root
// and, for nearly every call, no sin/cos — for the Buss–Fillmore average's Newton
// iteration, where every curve point averages nearby control points. Coarser than
// so3_jacobian_c: the truncation, θ⁶/1209600, is 1.6e-7 relative at 0.5. It stays
// apart (and its threshold with it) because the bf spline's outputs, its angular
// velocity included, depend on its last bits; the accurate c would change them.
inline double so3_jacobian_c_newton(double theta2) {
  if (theta2 < 0.25) return 1.0 / 12.0 + theta2 / 720.0 + theta2 * theta2 / 30240.0;
  const double theta = std::sqrt(theta2), half = 0.5 * theta;
  return (1.0 - half * std::cos(half) / std::sin(half)) / theta2;
}

// ---- the Jacobians -----------------------------------------------------------------------
// The products with a vector (…_times) skip forming the matrix.

// J_l(v)·x.
inline Vec3 so3_left_jacobian_times(const Vec3& v, const Vec3& x) {
  const double theta = v.norm();
  const Vec3 vx = v.cross(x);
  return x + so3_jacobian_a(theta) * vx + so3_jacobian_b(theta) * v.cross(vx);
}
// J_r(v)·x = J_l(−v)·x.
inline Vec3 so3_right_jacobian_times(const Vec3& v, const Vec3& x) { return so3_left_jacobian_times(-v, x); }

// J_l(v).
inline Mat3 so3_left_jacobian(const Vec3& v) {
  const double theta = v.norm();
  const Mat3 H = hat(v);
  return Mat3::Identity() + so3_jacobian_a(theta) * H + so3_jacobian_b(theta) * H * H;
}
// J_r(v) = J_l(−v).
inline Mat3 so3_right_jacobian(const Vec3& v) {
  const double theta = v.norm();
  const Mat3 H = hat(v);
  return Mat3::Identity() - so3_jacobian_a(theta) * H + so3_jacobian_b(theta) * H * H;
}

// J_l⁻¹(v)·x: the rate v̇ of a rotation vector whose quaternion turns at the
// fixed-frame angular velocity x. Zero when v or x is not finite (or the result
// overflows), as the rotation core answers non-finite input.
// With c = so3_jacobian_c(|v|) given, for a finite v (callers that apply one v to
// many x compute c once).
inline Vec3 so3_left_jacobian_inverse_times_with(const Vec3& v, const Vec3& x, double c) {
  if (!x.allFinite()) return Vec3::Zero();
  const Vec3 r = x - 0.5 * v.cross(x) + c * v.cross(v.cross(x));
  return r.allFinite() ? r : Vec3::Zero();
}
inline Vec3 so3_left_jacobian_inverse_times(const Vec3& v, const Vec3& x) {
  const double theta = v.norm();
  if (!std::isfinite(theta)) return Vec3::Zero();
  return so3_left_jacobian_inverse_times_with(v, x, so3_jacobian_c(theta));
}
// J_r⁻¹(v)·x = J_l⁻¹(−v)·x: the rate of v for the body angular velocity x.
inline Vec3 so3_right_jacobian_inverse_times(const Vec3& v, const Vec3& x) {
  return so3_left_jacobian_inverse_times(-v, x);
}

// I − ½[v]× + c·[v]×² for a given c = c(|v|), with [v]×² = vvᵀ − |v|²I (no matrix
// products).
inline Mat3 so3_left_jacobian_inverse_with(const Vec3& v, double c) {
  Mat3 m = c * (v * v.transpose());
  const double d = 1.0 - c * v.squaredNorm();
  m(0, 0) += d, m(1, 1) += d, m(2, 2) += d;
  m(0, 1) += 0.5 * v.z(), m(1, 0) -= 0.5 * v.z();
  m(0, 2) -= 0.5 * v.y(), m(2, 0) += 0.5 * v.y();
  m(1, 2) += 0.5 * v.x(), m(2, 1) -= 0.5 * v.x();
  return m;
}
// J_l⁻¹(v).
inline Mat3 so3_left_jacobian_inverse(const Vec3& v) {
  return so3_left_jacobian_inverse_with(v, so3_jacobian_c(v.norm()));
}
// J_r⁻¹(v) = J_l⁻¹(−v), column by column from the product (zero for non-finite v);
// c once for the three columns.
inline Mat3 so3_right_jacobian_inverse(const Vec3& v) {
  const Vec3 minus_v = -v;
  const double theta = minus_v.norm();
  if (!std::isfinite(theta)) return Mat3::Zero();
  const double c = so3_jacobian_c(theta);
  Mat3 m;
  for (int col = 0; col < 3; ++col) m.col(col) = so3_left_jacobian_inverse_times_with(minus_v, Vec3::Unit(col), c);
  return m;
}

// ---- rate terms ---------------------------------------------------------------------------
// For r(t) with ṙ = u: (d/dt J(r(t)))·u, the part of the angular acceleration of
// exp(r(t)) that is not J(r)·r̈ — body frame for J_r, fixed frame for J_l:
//   d/dt (J_r(r)·ṙ) = J_r(r)·r̈ + so3_right_jacobian_rate(r, ṙ).

// The coefficients of the J_r rate at one r, for callers that apply one r to many u
// (c2's fixed-point passes): no trigonometry per product.
struct So3RateCoefficients {
  double da, db, b;  // so3_jacobian_da, _db, _b at |r|
  explicit So3RateCoefficients(const Vec3& r) {
    const double theta = r.norm();
    da = so3_jacobian_da(theta), db = so3_jacobian_db(theta), b = so3_jacobian_b(theta);
  }
};
inline Vec3 so3_right_jacobian_rate_with(const Vec3& r, const Vec3& u, const So3RateCoefficients& k) {
  const double ru = r.dot(u);
  const Vec3 rxu = r.cross(u);
  return -k.da * ru * rxu + k.db * ru * r.cross(rxu) + k.b * u.cross(rxu);
}
inline Vec3 so3_right_jacobian_rate(const Vec3& r, const Vec3& u) {
  return so3_right_jacobian_rate_with(r, u, So3RateCoefficients(r));
}
// J_l(r) = J_r(−r), and −r moves at −u: the rate is −(the J_r rate at −r along u).
inline Vec3 so3_left_jacobian_rate(const Vec3& r, const Vec3& u) { return -so3_right_jacobian_rate(-r, u); }

}  // namespace rotinterp
