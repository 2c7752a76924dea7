// slerp: the piecewise geodesic through the keys (Shoemake 1985), shortest arc.
//
// Continuity C⁰ (angular velocity jumps at keys); coordinate-invariant; exact on
// constant angular velocity at any key spacing.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <cmath>
#include <memory>

namespace rotinterp {

namespace detail {
// b or −b at a·b = 0 exactly (slerp's 180° tie-break, below).
Quat slerp_tie_sign(const Quat& a, const Quat& b);
}  // namespace detail

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
  return great_arc_slerp(a, w < 0.0 ? Quat(-b.coeffs()) : detail::slerp_tie_sign(a, b), t);
}

// Builds the slerp interpolator (track validated; keys may be in either hemisphere).
Result<std::unique_ptr<Interpolator>> make_slerp(const RotationTrack& track);

}  // namespace rotinterp
