// slerp: the piecewise geodesic through the keys.
#include "rotinterp/interp/slerp.h"

#include "detail.h"

#include <cmath>

namespace rotinterp {

namespace {

class SlerpInterpolator final : public detail::SegmentInterpolator<SlerpInterpolator> {
 public:
  using SegmentInterpolator::SegmentInterpolator;
  Quat segment(std::size_t i, double u) const {
    // The keys themselves at the ends: what the formula gives there (bit for bit
    // at u = 0), without its asin and sincos — resampling at the source rate
    // evaluates nothing else.
    if (u <= 0.0) return k_.q[i];
    if (u >= 1.0) return k_.q[i + 1];
    return slerp(k_.q[i], k_.q[i + 1], u);
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
  return std::unique_ptr<Interpolator>(new SlerpInterpolator(std::move(*keys)));
}

}  // namespace rotinterp
