// c2: the C² rotation spline (continuous angular velocity and acceleration).
#include "rotinterp/interp/c2.h"

#include "body_cubic.h"
#include "rotinterp/core/so3_jacobian.h"

#include <cmath>
#include <vector>

namespace rotinterp {

namespace {

// One interior key k's row of the block-tridiagonal system, factored (index k − 1),
// with what each fixed-point pass needs of segment k − 1: its log, J_r⁻¹ and the
// rate term's coefficients, all computed once, so a pass is trig-free.
struct RateRow {
  Mat3 L, U, Dpinv, Jri_prev;
  Vec3 rho_prev, b0, y;
  So3RateCoefficients rate_prev;
  explicit RateRow(const Vec3& rho) : rho_prev(rho), rate_prev(rho) {}
};

// The interior body rates ω₁ … ωₙ₋₁ (see the header), block Thomas algorithm on
// 3×3 blocks, factored once in one pass over the keys, then a forward and a back
// sweep per fixed-point pass while the nonlinear term N changes them; the end rates
// are the end segments' mean rates.
std::vector<Vec3> c2_rates(const detail::Keys& k, const std::vector<Vec3>& rho, const C2Options& o) {
  const std::size_t n = rho.size();  // segments
  auto dt = [&](std::size_t i) { return k.t[i + 1] - k.t[i]; };
  std::vector<Vec3> w(n + 1);
  w[0] = rho[0] / dt(0);
  w[n] = rho[n - 1] / dt(n - 1);
  if (n < 2) return w;
  const std::size_t m = n - 1;  // unknowns: keys 1 … n−1 at index k−1
  std::vector<RateRow> rows;
  rows.reserve(m);
  // Factor: D′ₖ = Dₖ − Lₖ D′ₖ₋₁⁻¹ Uₖ₋₁, J_r⁻¹ of each segment computed once.
  Mat3 jri_next = so3_right_jacobian_inverse(rho[0]);
  for (std::size_t j = 0; j < m; ++j) {
    const double hp = dt(j), hn = dt(j + 1);
    RateRow& r = rows.emplace_back(rho[j]);
    r.Jri_prev = jri_next;
    jri_next = so3_right_jacobian_inverse(rho[j + 1]);
    r.L = (2.0 / hp) * so3_right_jacobian(rho[j]);
    r.U = (2.0 / hn) * jri_next;
    r.b0 = 6.0 * (rho[j] / (hp * hp) + rho[j + 1] / (hn * hn));
    const Mat3 D = (4.0 * (1.0 / hp + 1.0 / hn)) * Mat3::Identity();
    const Mat3 Dp = D - (j > 0 ? Mat3(r.L * rows[j - 1].Dpinv * rows[j - 1].U) : Mat3::Zero());
    r.Dpinv = Dp.inverse();
  }
  rows[0].b0 -= rows[0].L * w[0];
  rows[m - 1].b0 -= rows[m - 1].U * w[n];
  // Start from the mean of the adjacent segment rates.
  for (std::size_t k = 1; k <= m; ++k) w[k] = 0.5 * (rho[k - 1] / dt(k - 1) + rho[k] / dt(k));
  for (int it = 0; it < o.max_iterations; ++it) {
    for (std::size_t j = 0; j < m; ++j) {  // the right-hand side and the forward sweep together
      RateRow& r = rows[j];
      const Vec3 d = r.Jri_prev * w[j + 1];
      const Vec3 b = r.b0 - so3_right_jacobian_rate_with(r.rho_prev, d, r.rate_prev);
      r.y = b - (j > 0 ? Vec3(r.L * (rows[j - 1].Dpinv * rows[j - 1].y)) : Vec3::Zero());
    }
    bool done = true;
    Vec3 next = Vec3::Zero();
    for (std::size_t jj = m; jj-- > 0;) {
      const RateRow& r = rows[jj];
      const Vec3 x = r.Dpinv * (r.y - (jj + 1 < m ? Vec3(r.U * next) : Vec3::Zero()));
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
