#include "rotinterp/interp/slerp.h"

#include "detail.h"

#include <cmath>

namespace rotinterp {

Quat slerp(const Quat& a, const Quat& b_in, double t) {
  const Quat b = detail::align_pair(a, b_in);
  const double w = a.dot(b);  // cos φ ≥ 0, φ half the rotation angle
  // u ⟂ a with |u| = sin φ. For nearly equal keys w rounds to 1 and b − a is an
  // exact (Sterbenz) difference, so u keeps every digit the inputs have.
  const Eigen::Vector4d u = b.coeffs() - w * a.coeffs();
  const double s = u.norm();
  if (!(s > 0.0) || !std::isfinite(t)) return a;
  const double phi = std::atan2(s, w);
  const double tp = t * phi;
  Quat r;
  // sin(tφ)/s → t as s → 0 with both factors accurate: no cancellation.
  r.coeffs() = std::cos(tp) * a.coeffs() + (std::sin(tp) / s) * u;
  return r;
}

namespace {

class SlerpInterpolator final : public detail::SegmentInterpolator<SlerpInterpolator> {
 public:
  using SegmentInterpolator::SegmentInterpolator;
  Quat segment(std::size_t i, double u) const {
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

Result<std::unique_ptr<Interpolator>> make_slerp(const RotationTrack& track) {
  auto keys = detail::prepare(track);
  if (!keys) return make_error(keys.error());
  return std::unique_ptr<Interpolator>(new SlerpInterpolator(std::move(*keys)));
}

}  // namespace rotinterp
