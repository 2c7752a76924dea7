// gltf-cubic: glTF's CUBICSPLINE rotation sampler, as a viewer replays it.
#include "rotinterp/interp/gltf_cubic.h"

#include "detail.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {

// dq/dt = ½·ω̃·q for a fixed-frame angular velocity ω.
Eigen::Vector4d quat_rate(const Vec3& omega, const Quat& q) {
  const Quat w(0.0, 0.5 * omega.x(), 0.5 * omega.y(), 0.5 * omega.z());
  return (w * q).coeffs();
}

GltfCubicKeys tangents_for(detail::Keys k) {
  const std::size_t n = k.size();
  // Fixed-frame secant rates, the log of each step taken along its aligned keys'
  // own arc (not the core log's axis convention at exactly 180°, which may point
  // the other way: the tangents must follow the chord the Hermite cubic follows).
  std::vector<Vec3> v(n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Quat d = k.q[i + 1] * k.q[i].conjugate();  // d.w() = qᵢ₊₁·qᵢ ≥ 0 (aligned)
    const double s = d.vec().norm();
    const Vec3 step = s > 0.0 ? Vec3(d.vec() * (2.0 * half_angle(s, d.w()) / s)) : Vec3::Zero();
    v[i] = step / (k.t[i + 1] - k.t[i]);
  }
  std::vector<Eigen::Vector4d> m(n, Eigen::Vector4d::Zero());
  if (n >= 2) {
    m[0] = quat_rate(v[0], k.q[0]);
    m[n - 1] = quat_rate(v[n - 2], k.q[n - 1]);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double hp = k.t[i] - k.t[i - 1], hn = k.t[i + 1] - k.t[i];
      m[i] = quat_rate(detail::steffen_limited((hn * v[i - 1] + hp * v[i]) / (hp + hn), v[i - 1], v[i]), k.q[i]);
    }
  }
  for (Eigen::Vector4d& x : m)
    if (!x.allFinite()) x.setZero();
  return GltfCubicKeys{std::move(k.t), std::move(k.q), std::move(m)};
}

// The Hermite cubic of the components and its derivative in s.
struct Hermite {
  Eigen::Vector4d p, dp;
};
Hermite hermite(const Quat& q0, const Eigen::Vector4d& b0, const Quat& q1, const Eigen::Vector4d& a1, double dt, double s) {
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  Hermite h;
  h.p = h00 * q0.coeffs() + (dt * h10) * b0 + h01 * q1.coeffs() + (dt * h11) * a1;
  h.dp = d00 * q0.coeffs() + (dt * d10) * b0 + d01 * q1.coeffs() + (dt * d11) * a1;
  return h;
}

class GltfCubicInterpolator final : public detail::SegmentInterpolator<GltfCubicInterpolator> {
 public:
  GltfCubicInterpolator(detail::Keys keys, std::vector<Eigen::Vector4d> m)
      : SegmentInterpolator(std::move(keys)), m_(std::move(m)) {}
  Quat segment(std::size_t i, double u) const {
    if (u <= 0.0) return k_.q[i];
    if (u >= 1.0) return k_.q[i + 1];
    return gltf_cubic_segment(k_.q[i], m_[i], k_.q[i + 1], m_[i + 1], dt(i), u);
  }
  Vec3 segment_velocity(std::size_t i, double u) const {
    const Hermite h = hermite(k_.q[i], m_[i], k_.q[i + 1], m_[i + 1], dt(i), u);
    const double r = h.p.norm();
    if (!(r > 0.0)) return Vec3::Zero();
    const Eigen::Vector4d q = h.p / r;
    const Eigen::Vector4d qdot = (h.dp - q * q.dot(h.dp)) / (r * dt(i));  // d(p/|p|)/dt
    Quat qd, qq;
    qd.coeffs() = qdot;
    qq.coeffs() = q;
    return 2.0 * (qd * qq.conjugate()).vec();  // ω = 2·q̇·q⁻¹
  }

 private:
  std::vector<Eigen::Vector4d> m_;
};

}  // namespace

Quat gltf_cubic_segment(const Quat& q0, const Eigen::Vector4d& b0, const Quat& q1, const Eigen::Vector4d& a1, double dt,
                        double s) {
  const Eigen::Vector4d p = hermite(q0, b0, q1, a1, dt, s).p;
  const double r = p.norm();
  if (!(r > 0.0) || !std::isfinite(r)) return q0;
  Quat q;
  q.coeffs() = p / r;
  return q;
}

Result<GltfCubicKeys> gltf_cubic_keys(RotationTrack track) {
  auto keys = detail::prepare(std::move(track));
  if (!keys) return keys.failure();
  return tangents_for(std::move(*keys));
}

Result<std::unique_ptr<Interpolator>> make_gltf_cubic(RotationTrack track) {
  auto keys = gltf_cubic_keys(std::move(track));
  if (!keys) return keys.failure();
  detail::Keys k{std::move(keys->times), std::move(keys->keys)};
  return std::unique_ptr<Interpolator>(new GltfCubicInterpolator(std::move(k), std::move(keys->tangents)));
}

}  // namespace rotinterp
