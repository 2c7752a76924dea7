// nlerp: normalized linear blend of neighbouring keys, hemisphere-corrected.
//
// Continuity C⁰; coordinate-invariant (R·((1−h)a + hb)·S / |…| = nlerp(RaS, RbS));
// NOT constant speed: on a 90° segment the speed varies by ±17%, so it is not
// exact on constant angular velocity.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

// ((1−t)·a + t·b′)/|…| with b′ = ±b in a's hemisphere (the slerp tie-break at
// exactly 180°). a, b unit; t in [0, 1].
Quat nlerp(const Quat& a, const Quat& b, double t);

Result<std::unique_ptr<Interpolator>> make_nlerp(RotationTrack track);

}  // namespace rotinterp
