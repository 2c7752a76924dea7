// c2: the C² rotation spline (continuous angular velocity and acceleration).
#include "rotinterp/interp/c2.h"

#include "body_cubic.h"
#include "rotinterp/core/so3_jacobian.h"

#include <cmath>
#include <vector>

namespace rotinterp {

namespace {

// The interior body rates ω₁ … ωₙ₋₁ (see the header), block Thomas algorithm on
// 3×3 blocks, repeated while the nonlinear term N changes them; the end rates are
// the end segments' mean rates.
std::vector<Vec3> c2_rates(const detail::Keys& k, const std::vector<Vec3>& rho, const C2Options& o) {
  const std::size_t n = rho.size();  // segments
  auto dt = [&](std::size_t i) { return k.t[i + 1] - k.t[i]; };
  std::vector<Vec3> w(n + 1);
  w[0] = rho[0] / dt(0);
  w[n] = rho[n - 1] / dt(n - 1);
  if (n < 2) return w;
  const std::size_t m = n - 1;  // unknowns: keys 1 … n−1 at index k−1
  std::vector<Mat3> L(m), D(m), U(m), Jr(n), Jri(n);
  for (std::size_t i = 0; i < n; ++i) {
    Jr[i] = so3_right_jacobian(rho[i]);
    Jri[i] = so3_right_jacobian_inverse(rho[i]);
  }
  std::vector<Vec3> b0(m);
  for (std::size_t k = 1; k <= m; ++k) {
    const double hp = dt(k - 1), hn = dt(k);
    L[k - 1] = (2.0 / hp) * Jr[k - 1];
    D[k - 1] = (4.0 * (1.0 / hp + 1.0 / hn)) * Mat3::Identity();
    U[k - 1] = (2.0 / hn) * Jri[k];
    b0[k - 1] = 6.0 * (rho[k - 1] / (hp * hp) + rho[k] / (hn * hn));
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
  for (std::size_t k = 1; k <= m; ++k) w[k] = 0.5 * (rho[k - 1] / dt(k - 1) + rho[k] / dt(k));
  std::vector<Vec3> b(m), y(m);
  for (int it = 0; it < o.max_iterations; ++it) {
    for (std::size_t k = 1; k <= m; ++k) {
      const Vec3 d = Jri[k - 1] * w[k];
      b[k - 1] = b0[k - 1] - so3_right_jacobian_rate(rho[k - 1], d);
    }
    for (std::size_t j = 0; j < m; ++j) y[j] = b[j] - (j > 0 ? Vec3(L[j] * (Dpinv[j - 1] * y[j - 1])) : Vec3::Zero());
    bool done = true;
    Vec3 next = Vec3::Zero();
    for (std::size_t jj = m; jj-- > 0;) {
      const Vec3 x = Dpinv[jj] * (y[jj] - (jj + 1 < m ? Vec3(U[jj] * next) : Vec3::Zero()));
      if (!x.allFinite()) return w;  // keep the previous iterate
      if ((x - w[jj + 1]).cwiseAbs().maxCoeff() > o.tolerance * (1.0 + x.norm())) done = false;
      w[jj + 1] = x;
      next = x;
    }
    if (done) break;
  }
  return w;
}

}  // namespace

Result<std::unique_ptr<Interpolator>> make_c2(RotationTrack track, const C2Options& options) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  std::vector<Vec3> rho = detail::segment_logs(*keys);
  const std::vector<Vec3> w = rho.empty() ? std::vector<Vec3>{} : c2_rates(*keys, rho, options);
  return std::unique_ptr<Interpolator>(new detail::BodyCubic(std::move(*keys), std::move(rho), w));
}

}  // namespace rotinterp
