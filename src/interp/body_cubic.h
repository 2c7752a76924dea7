// Private (not installed): the curve c2 and clamped share. Segment i:
//   q(t) = qᵢ·exp(rᵢ(u)),  u = (t − tᵢ)/Δᵢ,
// rᵢ the cubic Hermite in the body-frame rotation vector with rᵢ(0) = 0,
// rᵢ(1) = ρᵢ = log(qᵢ⁻¹qᵢ₊₁), ṙᵢ(tᵢ) = ωᵢ and ṙᵢ(tᵢ₊₁) = J_r(ρᵢ)⁻¹ωᵢ₊₁, where ωₖ
// is the body angular velocity chosen at key k. The body rate at either end of a
// segment is then exactly ωₖ (J_r(0) = I, J_r(ρ)·J_r(ρ)⁻¹ = I): C¹ at every key,
// whatever the rates. The methods differ only in how they choose ωₖ.
#pragma once

#include "detail.h"
#include "rotinterp/core/so3_jacobian.h"

#include <vector>

namespace rotinterp::detail {

// ρᵢ = log(qᵢ⁻¹qᵢ₊₁) for every segment of prepared keys.
inline std::vector<Vec3> segment_logs(const Keys& k) {
  std::vector<Vec3> rho(k.size() < 2 ? 0 : k.size() - 1);
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = log(k.q[i].conjugate() * k.q[i + 1]).vec();
  return rho;
}

class BodyCubic final : public SegmentInterpolator<BodyCubic> {
 public:
  // rho from segment_logs(keys); w the body rate at every key (empty for < 2 keys).
  BodyCubic(Keys keys, std::vector<Vec3> rho, const std::vector<Vec3>& w)
      : SegmentInterpolator(std::move(keys)), rho_(std::move(rho)) {
    const std::size_t n = rho_.size();
    w_start_.resize(n);
    d_end_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      w_start_[i] = w[i];
      d_end_[i] = so3_right_jacobian_inverse_times(rho_[i], w[i + 1]);
    }
  }

  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];  // r(i, 0) = 0
    if (u >= 1.0) return k_.q[i + 1];
    return apply_moving(k_.q[i], RotVec(r(i, u)));
  }

  // ω = q·J_r(r)·ṙ (body rate J_r(r)ṙ, rotated to the fixed frame).
  Vec3 segment_velocity(std::size_t i, double u) const {
    const Vec3 rr = r(i, u);
    return apply_moving(k_.q[i], RotVec(rr)) * so3_right_jacobian_times(rr, r_dot(i, u));
  }
  // α = q·(J_r(r)·r̈ + (d/dt J_r(r))·ṙ): the body acceleration (scipy's
  // RotationSpline(t, 2)) rotated to the fixed frame.
  Vec3 segment_acceleration(std::size_t i, double u) const {
    const double h = dt(i);
    const Vec3 rddot =
        ((6.0 - 12.0 * u) * rho_[i] / h + (6.0 * u - 4.0) * w_start_[i] + (6.0 * u - 2.0) * d_end_[i]) / h;
    const Vec3 rr = r(i, u), rdot = r_dot(i, u);
    const Vec3 body = so3_right_jacobian_times(rr, rddot) + so3_right_jacobian_rate(rr, rdot);
    return apply_moving(k_.q[i], RotVec(rr)) * body;
  }

 private:
  Vec3 r(std::size_t i, double u) const {
    const double h = dt(i);
    const double u2 = u * u, u3 = u2 * u;
    return (u3 - 2.0 * u2 + u) * h * w_start_[i] + (-2.0 * u3 + 3.0 * u2) * rho_[i] + (u3 - u2) * h * d_end_[i];
  }

  // ṙ in t (rad/s).
  Vec3 r_dot(std::size_t i, double u) const {
    const double h = dt(i);
    const double u2 = u * u;
    return (6.0 * u - 6.0 * u2) * rho_[i] / h + (3.0 * u2 - 4.0 * u + 1.0) * w_start_[i] +
           (3.0 * u2 - 2.0 * u) * d_end_[i];
  }

  std::vector<Vec3> rho_;      // log(qᵢ⁻¹qᵢ₊₁)
  std::vector<Vec3> w_start_;  // ṙᵢ(tᵢ) = ωᵢ
  std::vector<Vec3> d_end_;    // ṙᵢ(tᵢ₊₁) = J_r(ρᵢ)⁻¹ωᵢ₊₁
};

}  // namespace rotinterp::detail
