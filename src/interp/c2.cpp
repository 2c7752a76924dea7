#include "rotinterp/interp/c2.h"

#include "detail.h"

#include <cmath>
#include <vector>

namespace rotinterp {

namespace {

class C2Interpolator final : public detail::SegmentInterpolator<C2Interpolator> {
 public:
  C2Interpolator(detail::Keys keys, const C2Options& o) : SegmentInterpolator(std::move(keys)) {
    const std::size_t nk = k_.size();
    if (nk < 2) return;
    const std::size_t n = nk - 1;  // segments
    rho_.resize(n);
    for (std::size_t i = 0; i < n; ++i) rho_[i] = log(k_.q[i].conjugate() * k_.q[i + 1]).vec();
    std::vector<Vec3> w(nk);  // body angular velocity at every key
    w[0] = rho_[0] / dt(0);
    w[n] = rho_[n - 1] / dt(n - 1);
    if (n >= 2) solve_interior(w, o);
    w_start_.resize(n);
    d_end_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      w_start_[i] = w[i];
      d_end_[i] = detail::right_jacobian_inverse_times(rho_[i], w[i + 1]);
    }
  }

  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];  // r(i, 0) = 0
    if (u >= 1.0) return k_.q[i + 1];
    return apply_moving(k_.q[i], RotVec(r(i, u)));
  }

  // ω = q·J_r(r)·ṙ (body rate J_r(r)ṙ, rotated to the fixed frame).
  Vec3 segment_velocity(std::size_t i, double u) const {
    const double h = dt(i);
    const double u2 = u * u;
    const Vec3 rdot = (6.0 * u - 6.0 * u2) * rho_[i] / h + (3.0 * u2 - 4.0 * u + 1.0) * w_start_[i] +
                      (3.0 * u2 - 2.0 * u) * d_end_[i];
    const Vec3 rr = r(i, u);
    return apply_moving(k_.q[i], RotVec(rr)) * detail::right_jacobian_times(rr, rdot);
  }

 private:
  // Cubic Hermite: r(0) = 0, r(Δ) = ρ, ṙ(0) = ωᵢ, ṙ(Δ) = J_r(ρ)⁻¹ωᵢ₊₁.
  Vec3 r(std::size_t i, double u) const {
    const double h = dt(i);
    const double u2 = u * u, u3 = u2 * u;
    return (u3 - 2.0 * u2 + u) * h * w_start_[i] + (-2.0 * u3 + 3.0 * u2) * rho_[i] + (u3 - u2) * h * d_end_[i];
  }

  // The interior rates ω₁ … ωₙ₋₁ (see the header), block Thomas algorithm on 3×3
  // blocks, repeated while the nonlinear term N changes them.
  void solve_interior(std::vector<Vec3>& w, const C2Options& o) {
    const std::size_t n = rho_.size();
    const std::size_t m = n - 1;  // unknowns: keys 1 … n−1 at index k−1
    std::vector<Mat3> L(m), D(m), U(m), Jr(n), Jri(n);
    for (std::size_t i = 0; i < n; ++i) {
      Jr[i] = detail::right_jacobian(rho_[i]);
      Jri[i] = detail::right_jacobian_inverse(rho_[i]);
    }
    std::vector<Vec3> b0(m);
    for (std::size_t k = 1; k <= m; ++k) {
      const double hp = dt(k - 1), hn = dt(k);
      L[k - 1] = (2.0 / hp) * Jr[k - 1];
      D[k - 1] = (4.0 * (1.0 / hp + 1.0 / hn)) * Mat3::Identity();
      U[k - 1] = (2.0 / hn) * Jri[k];
      b0[k - 1] = 6.0 * (rho_[k - 1] / (hp * hp) + rho_[k] / (hn * hn));
    }
    b0[0] -= L[0] * w[0];
    b0[m - 1] -= U[m - 1] * w[n];
    // Factor once: D′ₖ = Dₖ − Lₖ D′ₖ₋₁⁻¹ Uₖ₋₁.
    std::vector<Mat3> Dp(m), Dpinv(m);
    for (std::size_t j = 0; j < m; ++j) {
      Dp[j] = D[j] - (j > 0 ? Mat3(L[j] * Dpinv[j - 1] * U[j - 1]) : Mat3::Zero());
      Dpinv[j] = Dp[j].inverse();
    }
    // Start from the mean of the adjacent segment rates.
    for (std::size_t k = 1; k <= m; ++k) w[k] = 0.5 * (rho_[k - 1] / dt(k - 1) + rho_[k] / dt(k));
    std::vector<Vec3> b(m), y(m);
    for (int it = 0; it < o.max_iterations; ++it) {
      for (std::size_t k = 1; k <= m; ++k) {
        const Vec3 d = Jri[k - 1] * w[k];
        b[k - 1] = b0[k - 1] - detail::right_jacobian_rate_term(rho_[k - 1], d);
      }
      for (std::size_t j = 0; j < m; ++j) y[j] = b[j] - (j > 0 ? Vec3(L[j] * (Dpinv[j - 1] * y[j - 1])) : Vec3::Zero());
      bool done = true;
      Vec3 next = Vec3::Zero();
      for (std::size_t jj = m; jj-- > 0;) {
        const Vec3 x = Dpinv[jj] * (y[jj] - (jj + 1 < m ? Vec3(U[jj] * next) : Vec3::Zero()));
        if (!x.allFinite()) return;  // keep the previous iterate
        if ((x - w[jj + 1]).cwiseAbs().maxCoeff() > o.tolerance * (1.0 + x.norm())) done = false;
        w[jj + 1] = x;
        next = x;
      }
      if (done) break;
    }
  }

  std::vector<Vec3> rho_;      // log(qᵢ⁻¹qᵢ₊₁)
  std::vector<Vec3> w_start_;  // ṙᵢ(0) = ωᵢ
  std::vector<Vec3> d_end_;    // ṙᵢ(Δᵢ) = J_r(ρᵢ)⁻¹ωᵢ₊₁
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_c2(const RotationTrack& track, const C2Options& options) {
  auto keys = detail::prepare(track);
  if (!keys) return make_error(keys.error());
  return std::unique_ptr<Interpolator>(new C2Interpolator(std::move(*keys), options));
}

}  // namespace rotinterp
