// Grassia, "Practical parameterization of rotations using the exponential map"
// (1998): the derivatives of exp (§3) and the two-DOF swing parameterization with
// its elliptical joint limit (§5). Conventions as in rotation.h.
#pragma once

#include "rotinterp/core/rotation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>

namespace rotinterp {

// Below this angle (rad) ∂q/∂v uses the Taylor form of sin(θ/2)/θ. ⁴√ε ≈ 1.2e-4 is
// where the two-term series 1/2 − θ²/48 is exact to double precision (the next
// term, θ⁴/3840, is below ε/2 there) — Grassia §3.
inline const double kExpTaylorThreshold = std::pow(std::numeric_limits<double>::epsilon(), 0.25);

// Below this angle (rad) ∂q/∂v's d(sin(θ/2)/θ)/dθ / θ uses its series: the closed
// form cancels, losing about ε/θ² relatively (2e-12 at 1e-2), while three series
// terms are exact to ~1e-19 there.
constexpr double kDqDvSeries = 1e-2;

// ∂q/∂v, rows (w, x, y, z), columns (v_x, v_y, v_z).
Eigen::Matrix<double, 4, 3> dq_dv(const Vec3& v);
// ∂R/∂v_i for i = 0, 1, 2, R = exp(v) as a rotation matrix (chain rule through q).
std::array<Mat3, 3> dR_dv(const Vec3& v);

// Grassia §5: a two-DOF swing v = α·ŝ + β·t̂ in the plane perpendicular to a twist
// axis, with its chain rule and the elliptical joint-limit test.
struct SwingParam {
  Vec3 s;  // unit, ⟂ t and the twist axis
  Vec3 t;  // unit
  // Builds an orthonormal pair perpendicular to `twist_axis`.
  static SwingParam perpendicular_to(const Vec3& twist_axis);
  Vec3 vector(double alpha, double beta) const { return alpha * s + beta * t; }
  Quat orientation(double alpha, double beta) const { return rotinterp::exp(RotVec(vector(alpha, beta))); }
  // ∂q/∂(α, β) = ∂q/∂v · [ŝ t̂].
  Eigen::Matrix<double, 4, 2> dq_dswing(double alpha, double beta) const;
};
// (α/a)² + (β/b)² ≤ 1: inside the elliptical swing limit with semi-axes a, b > 0.
bool within_swing_limit(double alpha, double beta, double a, double b);

}  // namespace rotinterp
