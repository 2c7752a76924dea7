// Private helpers shared by the interpolators (not installed): track preparation,
// segment search, SO(3) Jacobians, the 180° tie-break.
#pragma once

#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace rotinterp::detail {

inline Quat negated(const Quat& q) { return Quat(-q.w(), -q.x(), -q.y(), -q.z()); }

// b or −b, whichever lies in a's hemisphere. When a·b is exactly 0 (orientations
// exactly 180° apart) the sign is the one for which the vector part of a⁻¹b has
// its first non-zero component positive — the core log's convention — so the path
// taken does not depend on the stored sign of b.
inline Quat align_pair(const Quat& a, const Quat& b) {
  const double d = a.dot(b);
  if (d > 0.0) return b;
  if (d < 0.0) return negated(b);
  const Vec3 v = (a.conjugate() * b).vec();
  for (int i = 0; i < 3; ++i)
    if (v[i] != 0.0) return v[i] < 0.0 ? negated(b) : b;
  return b;
}

// Times and keys of a track after preparation: validated (rules 1–3 of
// RotationTrack), normalized, signs aligned pairwise with align_pair.
struct Keys {
  std::vector<double> t;
  std::vector<Quat> q;
  std::size_t size() const { return t.size(); }
};

inline Result<Keys> prepare(const RotationTrack& track) {
  RotationTrack aligned = track;
  // Align signs first so that only rules 1–3 can fail: interpolators accept keys
  // in either hemisphere and take the short way (rule 4 is established here).
  for (std::size_t k = 1; k < aligned.keys.size() && k < aligned.times.size(); ++k)
    if (aligned.keys[k].coeffs().allFinite()) aligned.keys[k] = align_pair(aligned.keys[k - 1], aligned.keys[k]);
  if (Status s = aligned.validate(); !s) return make_error(s.error());
  Keys out;
  out.t = std::move(aligned.times);
  out.q.reserve(aligned.keys.size());
  for (std::size_t k = 0; k < aligned.keys.size(); ++k) {
    out.q.push_back(normalized_or_identity(aligned.keys[k]));
    if (k > 0) out.q[k] = align_pair(out.q[k - 1], out.q[k]);
  }
  return out;
}

// Position of t on a key timeline with ≥ 2 keys: segment i ∈ [0, n−2] and the
// normalized parameter u ∈ [0, 1]. Times outside [t₀, tₙ] (and NaN) clamp.
struct Where {
  std::size_t i;
  double u;
};

// `hint` is the segment of the previous call: sorted batches cost O(1) per sample.
inline Where locate(const std::vector<double>& t, double x, std::size_t& hint) {
  const std::size_t n = t.size();
  if (!(x > t.front())) return {hint = 0, 0.0};
  if (!(x < t.back())) return {hint = n - 2, 1.0};
  std::size_t i;
  if (hint + 1 < n && t[hint] <= x && x < t[hint + 1]) {
    i = hint;
  } else if (hint + 2 < n && t[hint + 1] <= x && x < t[hint + 2]) {
    i = hint + 1;
  } else {
    i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin()) - 1;
    i = std::min(i, n - 2);
  }
  hint = i;
  const double u = (x - t[i]) / (t[i + 1] - t[i]);
  return {i, std::clamp(u, 0.0, 1.0)};
}

// ---- SO(3) Jacobians -------------------------------------------------------------
// For R = exp(v): world angular velocity ω = J_l(v)·v̇ and body angular velocity
// ω_b = J_r(v)·v̇ with J_l(v) = I + a(θ)[v]× + b(θ)[v]×², J_r(v) = J_l(−v),
//   a = (1 − cos θ)/θ² = ½(sin(θ/2)/(θ/2))²  (cancellation-free),
//   b = (θ − sin θ)/θ³, series below kJacobianSeries.
// The inverse J_l⁻¹ is the core's rotvec_derivative.

// Below this angle (rad) b, a′/θ and b′/θ use their series to θ⁸: the truncation
// error there is < 1e-16 relative, while the closed forms lose 60ε/θ⁴ (b′/θ),
// i.e. 3e-12 at 0.25.
constexpr double kJacobianSeries = 0.25;

inline double jac_a(double th) {
  if (th == 0.0) return 0.5;
  const double h = 0.5 * th;
  const double s = std::sin(h) / h;
  return 0.5 * s * s;
}
inline double jac_b(double th) {
  const double t2 = th * th;
  if (th < kJacobianSeries)
    return 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362880.0 + t2 * t2 * t2 * t2 / 39916800.0;
  return (th - std::sin(th)) / (t2 * th);
}
// a′(θ)/θ and b′(θ)/θ.
inline double jac_da(double th) {
  const double t2 = th * th;
  if (th < kJacobianSeries)
    return -1.0 / 12.0 + t2 / 180.0 - t2 * t2 / 6720.0 + t2 * t2 * t2 / 453600.0 - t2 * t2 * t2 * t2 / 47900160.0;
  const double omc = 2.0 * std::sin(0.5 * th) * std::sin(0.5 * th);
  return (th * std::sin(th) - 2.0 * omc) / (t2 * t2);
}
inline double jac_db(double th) {
  const double t2 = th * th;
  if (th < kJacobianSeries)
    return -1.0 / 60.0 + t2 / 1260.0 - t2 * t2 / 60480.0 + t2 * t2 * t2 / 4989600.0 -
           t2 * t2 * t2 * t2 / 622702080.0;
  const double omc = 2.0 * std::sin(0.5 * th) * std::sin(0.5 * th);
  return (th * omc - 3.0 * (th - std::sin(th))) / (t2 * t2 * th);
}

// J_l(v)·x without forming the matrix.
inline Vec3 left_jacobian_times(const Vec3& v, const Vec3& x) {
  const double th = v.norm();
  const Vec3 vx = v.cross(x);
  return x + jac_a(th) * vx + jac_b(th) * v.cross(vx);
}
// J_r(v)·x = J_l(−v)·x.
inline Vec3 right_jacobian_times(const Vec3& v, const Vec3& x) { return left_jacobian_times(-v, x); }
inline Mat3 right_jacobian(const Vec3& v) {
  const double th = v.norm();
  const Mat3 H = hat(v);
  return Mat3::Identity() - jac_a(th) * H + jac_b(th) * H * H;
}
// J_r⁻¹(v)·x = J_l⁻¹(−v)·x.
inline Vec3 right_jacobian_inverse_times(const Vec3& v, const Vec3& x) { return rotvec_derivative(-v, x); }
inline Mat3 right_jacobian_inverse(const Vec3& v) {
  Mat3 m;
  for (int c = 0; c < 3; ++c) m.col(c) = right_jacobian_inverse_times(v, Vec3::Unit(c));
  return m;
}
// (d/dt J_r(r(t)))·ṙ for ṙ = u: the part of the body angular acceleration of
// exp(r(t)) that is not J_r·r̈.
inline Vec3 right_jacobian_rate_term(const Vec3& r, const Vec3& u) {
  const double th = r.norm();
  const double ru = r.dot(u);
  const Vec3 rxu = r.cross(u);
  return -jac_da(th) * ru * rxu + jac_db(th) * ru * r.cross(rxu) + jac_b(th) * u.cross(rxu);
}

// Fixed-frame angular velocity of t ↦ q(t) given body angular velocity ω_b.
inline Vec3 to_world(const Quat& q, const Vec3& body) { return q * body; }

// J_l⁻¹ coefficient c(θ) = (1 − (θ/2)cot(θ/2))/θ² (as in the core's rotvec_derivative).
inline double jac_inv_c(double th) {
  if (th < kSeriesThreshold) {
    const double t2 = th * th;
    return 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  }
  const double h = 0.5 * th;
  return (1.0 - h * std::cos(h) / std::sin(h)) / (th * th);
}
inline Mat3 left_jacobian_inverse(const Vec3& v) {
  const Mat3 H = hat(v);
  return Mat3::Identity() - 0.5 * H + jac_inv_c(v.norm()) * H * H;
}

// Base of every interpolator: a prepared key track, evaluation through a
// per-segment function of the derived class (CRTP, so batches inline it).
//   Derived::segment(i, u)            orientation on segment i at u ∈ [0, 1]
//   Derived::segment_velocity(i, u)   fixed-frame angular velocity there (rad/s)
template <class Derived>
class SegmentInterpolator : public Interpolator {
 public:
  explicit SegmentInterpolator(Keys keys) : k_(std::move(keys)) {}

  Quat evaluate(double t) const final {
    if (k_.size() == 1) return k_.q[0];
    std::size_t hint = 0;
    const Where w = locate(k_.t, t, hint);
    return self().segment(w.i, w.u);
  }
  void evaluate(const double* t, std::size_t n, Quat* out) const final {
    if (k_.size() == 1) {
      std::fill(out, out + n, k_.q[0]);
      return;
    }
    std::size_t hint = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const Where w = locate(k_.t, t[j], hint);
      out[j] = self().segment(w.i, w.u);
    }
  }
  bool has_angular_velocity() const final { return true; }
  // Zero outside [t₀, tₙ] (the curve is clamped there) and for one key.
  Vec3 angular_velocity(double t) const final {
    if (k_.size() == 1 || !(t >= k_.t.front() && t <= k_.t.back())) return Vec3::Zero();
    std::size_t hint = 0;
    const Where w = locate(k_.t, t, hint);
    const Vec3 v = self().segment_velocity(w.i, w.u);
    return v.allFinite() ? v : Vec3::Zero();
  }

 protected:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  double dt(std::size_t i) const { return k_.t[i + 1] - k_.t[i]; }
  Keys k_;
};

}  // namespace rotinterp::detail
