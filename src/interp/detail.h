// Private helpers shared by the interpolators (not installed): track preparation,
// segment search, the 180° tie-break. (The SO(3) Jacobians are public:
// rotinterp/core/so3_jacobian.h.)
#pragma once

#include "rotinterp/core/geodesic.h"
#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace rotinterp::detail {

inline Quat negated(const Quat& q) { return Quat(-q.w(), -q.x(), -q.y(), -q.z()); }

using rotinterp::align_pair;  // core/geodesic.h

// Steffen's limiter on rate vectors (clamped and gltf-cubic): p̂·min(|p|, 2|a|, 2|b|),
// zero unless a·b > 0 — a hold, a stop, a reversal or a turn of 90° or more.
inline Vec3 steffen_limited(const Vec3& p, const Vec3& a, const Vec3& b) {
  if (!(a.dot(b) > 0.0)) return Vec3::Zero();
  const double n = p.norm(), cap = 2.0 * std::min(a.norm(), b.norm());
  return n > cap ? Vec3(p * (cap / n)) : p;
}

// Times and keys of a track after preparation: validated (rules 1–3 of
// RotationTrack), normalized, signs aligned pairwise with align_pair.
struct Keys {
  std::vector<double> t;
  std::vector<Quat> q;
  std::size_t size() const { return t.size(); }
};

// Works in place on the track it is given: a track passed with std::move (the
// Python module's, built per call) becomes the interpolator's keys without a copy.
inline Result<Keys> prepare(RotationTrack track) {
  std::vector<Quat>& q = track.keys;
  // Align signs first so that only rules 1–3 can fail: interpolators accept keys
  // in either hemisphere and take the short way (rule 4 is established here).
  for (std::size_t k = 1; k < q.size() && k < track.times.size(); ++k)
    if (q[k].coeffs().allFinite()) q[k] = align_pair(q[k - 1], q[k]);
  if (Status s = track.validate(); !s) return s.failure();
  for (std::size_t k = 0; k < q.size(); ++k) {
    q[k] = normalized_or_identity(q[k]);
    if (k > 0) q[k] = align_pair(q[k - 1], q[k]);
  }
  return Keys{std::move(track.times), std::move(q)};
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

// Base of every interpolator: a prepared key track, evaluation through a
// per-segment function of the derived class (CRTP, so batches inline it).
//   Derived::segment(i, u)            orientation on segment i at u ∈ [0, 1]
//   Derived::segment_velocity(i, u)   fixed-frame angular velocity there (rad/s)
//   Derived::segment_acceleration(i, u)  optional: its derivative in t (rad/s²);
//                                     without it, the difference quotient below
//   Derived::segments(w, m, out)      optional, with kBatchSegments = true: out[j] =
//                                     segment(w[j].i, w[j].u) for m ≤ kSegmentBlock
template <class Derived>
class SegmentInterpolator : public Interpolator {
 public:
  explicit SegmentInterpolator(Keys keys) : k_(std::move(keys)) {}
  static constexpr bool kBatchSegments = false;
  static constexpr std::size_t kSegmentBlock = 64;  // samples per segments() call

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
    if constexpr (Derived::kBatchSegments) {
      // Located a block at a time, then evaluated together (Derived::segments), so
      // the per-sample arithmetic runs as one vectorizable loop.
      Where w[kSegmentBlock];
      for (std::size_t j0 = 0; j0 < n; j0 += kSegmentBlock) {
        const std::size_t m = std::min(kSegmentBlock, n - j0);
        for (std::size_t j = 0; j < m; ++j) w[j] = locate(k_.t, t[j0 + j], hint);
        self().segments(w, m, out + j0);
      }
    } else {
      for (std::size_t j = 0; j < n; ++j) {
        const Where w = locate(k_.t, t[j], hint);
        out[j] = self().segment(w.i, w.u);
      }
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
  bool has_angular_acceleration() const final { return true; }
  Vec3 angular_acceleration(double t) const final {
    if (k_.size() == 1 || !(t >= k_.t.front() && t <= k_.t.back())) return Vec3::Zero();
    std::size_t hint = 0;
    const Where w = locate(k_.t, t, hint);
    const Vec3 a = self().segment_acceleration(w.i, w.u);
    return a.allFinite() ? a : Vec3::Zero();
  }

  // For methods without a closed form (a derived class hides it with its own): the
  // second-order difference quotient of the closed-form segment_velocity in u, inside
  // the segment (one-sided three-point at its ends, so never across a key, where
  // C¹ methods jump). Step 1e-5 of the segment, near ε^(1/3): truncation and
  // round-off both about 1e-10 of the scale of ω.
  Vec3 segment_acceleration(std::size_t i, double u) const {
    return difference_quotient(i, u, [this, i](double x) { return self().segment_velocity(i, x); });
  }

 protected:
  // d/dt of velocity(u) on segment i, by the quotient described above.
  template <class Velocity>
  Vec3 difference_quotient(std::size_t i, double u, const Velocity& v) const {
    constexpr double h = 1e-5;
    const double per_u = 1.0 / dt(i);  // du/dt
    if (u - h < 0.0) return (-3.0 * v(u) + 4.0 * v(u + h) - v(u + 2.0 * h)) * (per_u / (2.0 * h));
    if (u + h > 1.0) return (3.0 * v(u) - 4.0 * v(u - h) + v(u - 2.0 * h)) * (per_u / (2.0 * h));
    return (v(u + h) - v(u - h)) * (per_u / (2.0 * h));
  }

  const Derived& self() const { return static_cast<const Derived&>(*this); }
  double dt(std::size_t i) const { return k_.t[i + 1] - k_.t[i]; }
  Keys k_;
};

// The slerp method's curve by the exact core slerp instead of its polynomial kernel
// (slerp.cpp): for callers that need points exactly on the geodesic (bf's knots).
Result<std::unique_ptr<Interpolator>> make_exact_slerp(RotationTrack track);

}  // namespace rotinterp::detail
