// nlerp: the normalized linear blend of neighbouring keys.
#include "rotinterp/interp/nlerp.h"

#include "detail.h"

namespace rotinterp {

Quat nlerp(const Quat& a, const Quat& b_in, double t) {
  const Quat b = detail::align_pair(a, b_in);
  Quat p;
  p.coeffs() = (1.0 - t) * a.coeffs() + t * b.coeffs();
  return normalized_or_identity(p);
}

namespace {

class NlerpInterpolator final : public detail::SegmentInterpolator<NlerpInterpolator> {
 public:
  using SegmentInterpolator::SegmentInterpolator;
  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];
    if (u >= 1.0) return k_.q[i + 1];
    return nlerp(k_.q[i], k_.q[i + 1], u);
  }
  Vec3 segment_velocity(std::size_t i, double u) const {
    // q = p/|p|, p = (1−u)a + ub: q̇ = (ṗ − q(q·ṗ))/|p|, ω = 2·vec(q̇ q⁻¹).
    const Quat& a = k_.q[i];
    const Quat& b = k_.q[i + 1];
    Quat p;
    p.coeffs() = (1.0 - u) * a.coeffs() + u * b.coeffs();
    const double n = p.norm();
    const Quat q(p.coeffs() / n);
    const Eigen::Vector4d pdot = (b.coeffs() - a.coeffs()) / dt(i);
    Quat qdot;
    qdot.coeffs() = (pdot - q.coeffs() * q.coeffs().dot(pdot)) / n;
    return 2.0 * (qdot * q.conjugate()).vec();
  }
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_nlerp(RotationTrack track) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  return std::unique_ptr<Interpolator>(new NlerpInterpolator(std::move(*keys)));
}

}  // namespace rotinterp
