// slerp: the piecewise geodesic through the keys (Shoemake 1985), shortest arc.
//
// Continuity C⁰ (angular velocity jumps at keys); coordinate-invariant; exact on
// constant angular velocity at any key spacing. Sampled by the polynomial kernel
// (core/slerp_kernel.h): to round-off for key steps up to 83°, within 1e-7 rad
// (kSlerpKernelMaxError) of the exact geodesic beyond; keys are hit bit for bit.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/geodesic.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>

namespace rotinterp {

// Builds the slerp interpolator (track validated; keys may be in either hemisphere).
Result<std::unique_ptr<Interpolator>> make_slerp(RotationTrack track);

}  // namespace rotinterp
