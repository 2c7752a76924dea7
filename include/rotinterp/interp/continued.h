// Curves continued past their end keys at their end angular velocity.
//
// Every method clamps outside [t₀, tₙ]: the curve holds its end key, and its angular
// velocity and acceleration are zero there. A continued curve instead turns on at
// the velocity it has at the end key — ω(tₙ), the last segment's limit, and ω(t₀)
// before the first key — with zero acceleration beyond:
//   q(t) = exp((t − tₙ)·ω(tₙ)) · qₙ  for t > tₙ   (fixed-frame ω; alike before t₀).
// So the curve stays C¹ across its end keys (orientation and velocity continue), and
// its body-frame velocity is constant beyond them. scipy's RotationSpline extends
// its last cubic instead, which keeps turning faster or slower; this extension
// never overshoots a rotation the keys did not show the rate of.
// For the methods with a velocity at their keys (continuity ≥ 1): for slerp and
// nlerp the end velocity is an artifact of the last chord, so they are refused.
#pragma once

#include "rotinterp/interp/interpolator.h"

#include <memory>
#include <string>

namespace rotinterp {

// Whether `m` can be continued (its curve has a velocity at its end keys).
bool can_continue(const MethodInfo& m);
// Comma-separated names of the methods can_continue takes, for messages.
std::string continued_method_names();

// `curve` (built on keys from t₀ to tₙ) continued at its end velocities beyond them.
std::unique_ptr<Interpolator> continue_at_end_velocity(std::unique_ptr<Interpolator> curve, double t0, double tn);

}  // namespace rotinterp
