// Periodic curves: an interpolator for a track that is one period of a cycle.
//
// A cycle's track is given in open form: keys at t₀ < … < tₙ₋₁ and a period P
// with tₙ₋₁ < t₀ + P; the key at t₀ + P is q₀ again (the closed form, whose last
// key repeats the first, is the open form without its last key and P = tₙ₋₁ − t₀).
// The curve passes through qₖ at tₖ + m·P for every whole m, is defined at every
// t (no clamping: t is taken modulo P) and is as smooth across the seam t₀ + m·P
// as between any two keys: C¹ for the C¹ methods, C² for c2, expmap-c2 and bf.
// Starting the cycle at another key (rotating the key list, times shifted by P)
// gives the same curve.
//
// How: every method is built on the cycle unrolled — the open keys repeated, times
// shifted by whole periods, kPeriodicPadding keys on each side — and evaluated on
// its middle period. The local methods (slerp, nlerp, squad, clamped, gltf-cubic,
// expmap) look at most two keys away, so their curve there is exactly the periodic
// one. The C² methods solve a global system whose end conditions reach inward
// damped by a factor of at most 1/2 per key (2 − √3 ≈ 0.27 at uniform spacing):
// after 64 keys that is below 2⁻⁶⁴ ≈ 5e-20, under round-off, so the middle period
// equals the solution of the cyclic system to round-off (docs/methods.md).
#pragma once

#include "rotinterp/interp/interpolator.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

namespace rotinterp {

// Keys added on each side of the period when the cycle is unrolled (see above).
inline constexpr std::size_t kPeriodicPadding = 64;

// Builds `method` on the cycle whose open-form keys are `track` (rules 1–3 of
// RotationTrack) and whose period is `period` seconds. Errors: those of the method,
// an unknown method, a period that is not finite or not longer than tₙ₋₁ − t₀.
Result<std::unique_ptr<Interpolator>> make_periodic_interpolator(std::string_view method, const RotationTrack& track,
                                                                 double period);

// A joint's curve through its keys: the periodic one when `period` is given (a joint
// that closes its cycle), otherwise the method's own (make_interpolator). The one
// place that choice is made: resample --loop (clip/resample_loop.h), the rebuild
// eval and render measure (clip/rebuild.h) and reduce --loop all call it.
Result<std::unique_ptr<Interpolator>> make_joint_curve(std::string_view method, const RotationTrack& keys,
                                                       std::optional<double> period);

}  // namespace rotinterp
