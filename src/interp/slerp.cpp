// slerp: the piecewise geodesic through the keys, by the polynomial slerp kernel.
#include "rotinterp/interp/slerp.h"

#include "detail.h"
#include "rotinterp/core/slerp_kernel.h"

#include <cmath>

namespace rotinterp {

namespace {

// Exact: the core slerp, one sample at a time (bf's in-between knots, which must lie
// on the geodesic to keep bf exact on constant angular velocity). Otherwise the
// polynomial kernel, within kSlerpKernelMaxError of it (core/slerp_kernel.h).
template <bool Exact>
class SlerpInterpolator final : public detail::SegmentInterpolator<SlerpInterpolator<Exact>> {
  using Base = detail::SegmentInterpolator<SlerpInterpolator<Exact>>;
  using Base::k_;
  using Base::dt;

 public:
  using Base::kSegmentBlock;
  explicit SlerpInterpolator(detail::Keys keys) : Base(std::move(keys)) {}
  static constexpr bool kBatchSegments = !Exact;

  Quat segment(std::size_t i, double u) const {
    // The keys themselves at the ends, bit for bit (resampling at the source rate
    // evaluates nothing else).
    if (u <= 0.0) return k_.q[i];
    if (u >= 1.0) return k_.q[i + 1];
    return Exact ? slerp(k_.q[i], k_.q[i + 1], u) : slerp_poly(k_.q[i], k_.q[i + 1], u);
  }

  // segment() for a block: the keys at the ends (half the samples when resampling to
  // twice the key rate) written at once, the others gathered into component arrays
  // for one kernel call.
  void segments(const detail::Where* w, std::size_t m, Quat* out) const {
    double a[4][kSegmentBlock], b[4][kSegmentBlock], u[kSegmentBlock], r[4][kSegmentBlock];
    std::size_t inside[kSegmentBlock];
    std::size_t k = 0;
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t i = w[j].i;
      if (w[j].u <= 0.0) {
        out[j] = k_.q[i];
      } else if (w[j].u >= 1.0) {
        out[j] = k_.q[i + 1];
      } else {
        const Quat &p = k_.q[i], &q = k_.q[i + 1];
        a[0][k] = p.w(), a[1][k] = p.x(), a[2][k] = p.y(), a[3][k] = p.z();
        b[0][k] = q.w(), b[1][k] = q.x(), b[2][k] = q.y(), b[3][k] = q.z();
        u[k] = w[j].u;
        inside[k++] = j;
      }
    }
    slerp_arrays({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}, u, k, {r[0], r[1], r[2], r[3]});
    for (std::size_t s = 0; s < k; ++s) out[inside[s]] = Quat(r[0][s], r[1][s], r[2][s], r[3][s]);
  }

  Vec3 segment_velocity(std::size_t i, double) const {
    // q(t) = qᵢ·exp(s·ρ), ρ = log(qᵢ⁻¹qᵢ₊₁) (signs aligned by align_pair, so the
    // core log reports the same axis slerp follows): ω = qᵢ·ρ/Δᵢ.
    const RotVec rho = log(k_.q[i].conjugate() * k_.q[i + 1]);
    return k_.q[i] * (rho.vec() / dt(i));
  }
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_slerp(RotationTrack track) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  return std::unique_ptr<Interpolator>(new SlerpInterpolator<false>(std::move(*keys)));
}

Result<std::unique_ptr<Interpolator>> detail::make_exact_slerp(RotationTrack track) {
  auto keys = prepare(std::move(track));
  if (!keys) return keys.failure();
  return std::unique_ptr<Interpolator>(new SlerpInterpolator<true>(std::move(*keys)));
}

}  // namespace rotinterp
