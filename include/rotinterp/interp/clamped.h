// clamped: a C¹ shape-preserving interpolator — holds stay still, stops and
// reversals do not overshoot. The analogue on SO(3) of Steffen's monotone cubic
// (A&A 239, 1990), which the translation curves use for the same reason.
//
// The curve is c2's (segment i: q = qᵢ·exp(rᵢ), rᵢ a cubic Hermite in the body
// rotation vector from 0 to ρᵢ = log(qᵢ⁻¹qᵢ₊₁)), with the body angular velocity ωₖ
// at each key chosen by a limiter in key k's tangent space instead of a global
// solve. At an interior key, with the incoming and outgoing secant rates
// v₋ = ρₖ₋₁/Δₖ₋₁ and v₊ = ρₖ/Δₖ (both body-frame vectors at key k) and Steffen's
// parabola rate p = (Δₖ·v₋ + Δₖ₋₁·v₊)/(Δₖ₋₁ + Δₖ):
//   ωₖ = 0                                  if v₋·v₊ ≤ 0 (a hold on either side, a
//                                            stop, a reversal, or a turn of 90° or more)
//   ωₖ = p̂ · min(|p|, 2|v₋|, 2|v₊|)         otherwise.
// End keys: the end segment's mean rate ρ/Δ, as c2 (Steffen's one-sided parabola
// extrapolates an accelerating end beyond the end secant's speed: 2.15°/ms on keys
// 0°, 20°, 170° at 10 Hz, where every segment stays below 2°/ms). Two keys: slerp.
//
// What it guarantees (tests/interp/test_clamped.cpp):
//  * Holds: a segment between equal keys is exactly still (both its rates are 0).
//  * A key where the motion stops or reverses has zero angular velocity.
//  * No overshoot along the arc: p·v± > 0 and |ωₖ| ≤ 2|v±|, so each segment's
//    progress along its key-to-key arc, r·ρ̂, is a cubic from 0 to |ρ| with end
//    slopes in [0, 2|ρ|] — monotone: it never passes either key.
//  * Sideways, r leaves the arc by at most (4/27)(|m₀⊥| + |m₁⊥|) ≤ (4/27)(2 + π)|ρ|
//    ≈ 0.76|ρ| (m the end tangents; 4/27 = max of the Hermite basis h₁₀, h₁₁; |m₀| ≤
//    2|ρ|, and J_r(ρ)⁻¹ stretches the perpendicular part by (θ/2)/sin(θ/2) ≤ π/2).
//  * C¹ (the rates are shared by both sides of a key); not C²; coordinate-
//    invariant (only body-frame logs, dot products and norms); exact on constant
//    angular velocity at any spacing (v₋ = v₊ = p there); through every key.
// Accuracy on smooth motion is h³, like squad (the limiter is inactive there,
// p is a second-order rate).
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

Result<std::unique_ptr<Interpolator>> make_clamped(RotationTrack track);

}  // namespace rotinterp
