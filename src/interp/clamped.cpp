// clamped: the C¹ shape-preserving interpolator (Steffen's monotone cubic on SO(3)).
#include "rotinterp/interp/clamped.h"

#include "body_cubic.h"

#include <algorithm>
#include <vector>

namespace rotinterp {

namespace {

// The body rate at every key (see the header).
std::vector<Vec3> clamped_rates(const detail::Keys& k, const std::vector<Vec3>& rho) {
  const std::size_t n = rho.size();  // segments, ≥ 1
  auto dt = [&](std::size_t i) { return k.t[i + 1] - k.t[i]; };
  std::vector<Vec3> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = rho[i] / dt(i);
  std::vector<Vec3> w(n + 1);
  for (std::size_t i = 1; i < n; ++i) {
    // ρᵢ₋₁ is the same body vector at key i−1 and at key i (the axis of the step).
    const double hp = dt(i - 1), hn = dt(i);
    w[i] = detail::steffen_limited((hn * v[i - 1] + hp * v[i]) / (hp + hn), v[i - 1], v[i]);
  }
  // End keys: the end segment's mean rate (as c2). Steffen's one-sided parabola
  // would extrapolate an accelerating end past the end secant's speed.
  w[0] = v[0];
  w[n] = v[n - 1];
  return w;
}

}  // namespace

Result<std::unique_ptr<Interpolator>> make_clamped(RotationTrack track) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  std::vector<Vec3> rho = detail::segment_logs(*keys);
  const std::vector<Vec3> w = rho.empty() ? std::vector<Vec3>{} : clamped_rates(*keys, rho);
  return std::unique_ptr<Interpolator>(new detail::BodyCubic(std::move(*keys), std::move(rho), w));
}

}  // namespace rotinterp
