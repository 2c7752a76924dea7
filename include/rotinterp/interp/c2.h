// c2: C² interpolation with continuous angular velocity AND angular acceleration
// (the method of scipy's RotationSpline).
//
// Segment i: q(t) = qᵢ·exp(rᵢ(t − tᵢ)), rᵢ a cubic Hermite in the body-frame
// rotation vector with rᵢ(0) = 0, rᵢ(Δᵢ) = ρᵢ = log(qᵢ⁻¹qᵢ₊₁), ṙᵢ(0) = ωᵢ and
// ṙᵢ(Δᵢ) = J_r(ρᵢ)⁻¹ωᵢ₊₁, where ωₖ is the body angular velocity at key k. The
// end rates are the end segments' mean rates (ω₀ = ρ₀/Δ₀, ωₙ = ρₙ₋₁/Δₙ₋₁); the
// interior rates solve the block-tridiagonal system that makes the angular
// acceleration continuous:
//   2/Δₖ₋₁·J_r(ρₖ₋₁)ωₖ₋₁ + 4(1/Δₖ₋₁ + 1/Δₖ)ωₖ + 2/Δₖ·J_r(ρₖ)⁻¹ωₖ₊₁
//       = 6(ρₖ₋₁/Δₖ₋₁² + ρₖ/Δₖ²) − N(ρₖ₋₁, J_r(ρₖ₋₁)⁻¹ωₖ),
// N the rate-of-change term (d/dt J_r)·ṙ, handled by fixed-point iteration.
// Interpolating, coordinate-invariant (only body-frame logs are used), exact on
// constant angular velocity at any key spacing, C² at interior keys.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

struct C2Options {
  // Stop the fixed-point iteration on N when no rate changes by more than
  // tolerance·(1 + |ω|) (rad/s).
  double tolerance = 1e-13;
  // Iteration cap; the last iterate is kept (the curve still passes through the
  // keys, only the acceleration continuity is then approximate).
  int max_iterations = 100;
};

Result<std::unique_ptr<Interpolator>> make_c2(RotationTrack track, const C2Options& options = {});

}  // namespace rotinterp
