// The geodesic of S³ between two unit quaternions: the one slerp every layer uses
// (the slerp method, the track sampler, squad's inner blends).
#pragma once

#include "rotinterp/core/rotation.h"

#include <cmath>

namespace rotinterp {

// b or −b, whichever lies in a's hemisphere. When a·b is exactly 0 (orientations
// exactly 180° apart) the sign is the one for which the vector part of a⁻¹b has
// its first non-zero component positive — the core log's convention — so the path
// taken does not depend on the stored sign of b.
inline Quat align_pair(const Quat& a, const Quat& b) {
  const double d = a.dot(b);
  const Quat minus_b(-b.w(), -b.x(), -b.y(), -b.z());
  if (d > 0.0) return b;
  if (d < 0.0) return minus_b;
  const Vec3 v = (a.conjugate() * b).vec();
  for (int i = 0; i < 3; ++i)
    if (v[i] != 0.0) return v[i] < 0.0 ? minus_b : b;
  return b;
}

// The point at parameter t on the great arc of S³ from a to b AS STORED: no
// hemisphere flip, so for a·b < 0 it takes the long way (a rotation past 180°).
// Shoemake's squad blends its control points and its two inner curves with this
// slerp: a shortest-arc blend flips hemisphere wherever the dot product of the
// blended points changes sign, a jump of up to 180° within one sample. Same
// accuracy as slerp (asin where |a·b| is large, acos elsewhere); for a = −b
// (no arc defined) it returns a.
inline Quat great_arc_slerp(const Quat& a, const Quat& b, double t) {
  const double w = a.dot(b);  // cos φ, φ ∈ [0, π] the 4-D angle from a to b
  const Eigen::Vector4d u = b.coeffs() - w * a.coeffs();
  const double s = u.norm();  // sin φ
  if (!(s > 0.0) || !std::isfinite(t)) return a;
  const double phi = s <= std::abs(w) ? (w > 0.0 ? std::asin(s) : kPi - std::asin(s)) : std::acos(w);
  const double tp = t * phi;
  Quat r;
  r.coeffs() = std::cos(tp) * a.coeffs() + (std::sin(tp) / s) * u;
  return r;
}

// The point at parameter t on the shortest geodesic from a (t = 0) to b (t = 1),
// i.e. a·exp(t·log(a⁻¹b)) with b taken in a's hemisphere. a and b are unit.
//
// Accuracy: computed as cos(tφ)·a + (sin(tφ)/|u|)·u with u = b − (a·b)·a, the
// part of b orthogonal to a (|u| = sin φ, φ half the rotation angle), and
// φ = asin|u| when |u| ≤ a·b (φ ≤ 45°), acos(a·b) otherwise — each used only
// where it is well-conditioned; never acos of a dot product near 1, and
// sin(tφ)/|u| → t without cancellation as |u| → 0. For keys 1e-9 rad apart the
// result is on the geodesic at angle t·1e-9 to ~1e-7 relative; for a = b (or a·b
// rounding to one ulp above 1) it is a to an ulp.
// Keys exactly 180° apart (a·b = 0): the path is a rotation by +180°·t about the
// axis of log(a⁻¹b) as the core log reports it (first non-zero component
// positive), so the path does not depend on the stored sign of b.
// t outside [0, 1] extrapolates along the same geodesic.
// Inline: it is the inner loop of resampling.
inline Quat slerp(const Quat& a, const Quat& b, double t) {
  const double w = a.dot(b);
  if (w > 0.0) return great_arc_slerp(a, b, t);
  // b's hemisphere flipped to a's (an exact negation), or the tie at exactly 180°.
  return great_arc_slerp(a, w < 0.0 ? Quat(-b.coeffs()) : align_pair(a, b), t);
}

}  // namespace rotinterp
