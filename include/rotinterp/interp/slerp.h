// slerp: the piecewise geodesic through the keys (Shoemake 1985), shortest arc.
//
// Continuity C⁰ (angular velocity jumps at keys); coordinate-invariant; exact on
// constant angular velocity at any key spacing.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

// The point at parameter t on the shortest geodesic from a (t = 0) to b (t = 1),
// i.e. a·exp(t·log(a⁻¹b)) with b taken in a's hemisphere. a and b are unit.
//
// Accuracy: computed as cos(tφ)·a + (sin(tφ)/|u|)·u with u = b − (a·b)·a and
// φ = atan2(|u|, a·b) (half the rotation angle). No acos of a dot product and no
// division by sin φ ≈ 0: for keys 1e-9 rad apart the result is on the geodesic at
// angle t·1e-9 to ~1e-7 relative; for a = b (or a·b one ulp above 1) it is a.
// Keys exactly 180° apart (a·b = 0): the path is a rotation by +180°·t about the
// axis of log(a⁻¹b) as the core log reports it (first non-zero component
// positive), so the path does not depend on the stored sign of b.
// t outside [0, 1] extrapolates along the same geodesic.
Quat slerp(const Quat& a, const Quat& b, double t);

// Builds the slerp interpolator (track validated; keys may be in either hemisphere).
Result<std::unique_ptr<Interpolator>> make_slerp(const RotationTrack& track);

}  // namespace rotinterp
