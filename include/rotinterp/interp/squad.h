// squad: Shoemake's spherical quadrangle interpolation, with control points for
// non-uniform key times.
//
// Segment i (keys qᵢ, qᵢ₊₁ at tᵢ, tᵢ₊₁, h = (t − tᵢ)/(tᵢ₊₁ − tᵢ)):
//   Squad = slerp(slerp(qᵢ, qᵢ₊₁, h), slerp(aᵢ, bᵢ₊₁, h), 2h(1−h))
// with Lₖ = log(qₖ⁻¹qₖ₊₁) (the core's full-angle rotation vector, paired with the
// core exp — the ¼ below is then the same ¼ as Shoemake's half-angle formula) and
// Δₖ = tₖ₊₁ − tₖ:
//   outgoing control  aᵢ   = qᵢ  ·exp(¼(Lᵢ₋₁·Δᵢ/Δᵢ₋₁ − Lᵢ))
//   incoming control  bᵢ₊₁ = qᵢ₊₁·exp(¼(Lᵢ − Lᵢ₊₁·Δᵢ/Δᵢ₊₁))
// (the logs scaled by the adjacent intervals as in the quaternionic package).
// For uniform keys aᵢ = bᵢ = sᵢ = qᵢ·exp(−(log(qᵢ⁻¹qᵢ₊₁) + log(qᵢ⁻¹qᵢ₋₁))/4), the
// textbook (and glm::intermediate) control point. The angular velocity at key i is
// then ½(Lᵢ₋₁/Δᵢ₋₁ + Lᵢ/Δᵢ) (body frame) from both sides: C¹ at any spacing.
//
// End keys: a reflected phantom key q₋₁ = q₀q₁⁻¹q₀ one interval Δ₀ before the
// first key (and qₙ₊₁ = qₙqₙ₋₁⁻¹qₙ after the last), so that L₋₁ = L₀ and the end
// control point is the key itself. squad is therefore exact on constant angular
// velocity, uniform or not, including the end segments (duplicating the end key
// instead would bend them).
//
// Signs: the keys are aligned (qᵢ·qᵢ₊₁ ≥ 0) and each control point is computed
// from its key, once, when the track is built; the three blends then never flip
// hemisphere. (Shortest-arc blends flip where a·b, or the dot of the two inner
// points, changes sign mid-segment — keys about 100° or more apart — and the
// curve jumped by up to 180° within one sample.)
//
// Continuity C¹; coordinate-invariant. Extreme interval ratios (Δᵢ/Δᵢ₋₁ ≫ 1)
// scale the incoming log and give large loops — finite, but large.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

// One squad segment: slerp(slerp(q0, q1, h), slerp(a, b, h), 2h(1−h)) with every
// slerp along the great arc as stored (great_arc_slerp, Shoemake's and glm's
// `mix`), never flipped to the short side.
Quat squad(const Quat& q0, const Quat& q1, const Quat& a, const Quat& b, double h);

Result<std::unique_ptr<Interpolator>> make_squad(RotationTrack track);

}  // namespace rotinterp
