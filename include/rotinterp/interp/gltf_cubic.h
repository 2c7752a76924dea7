// gltf-cubic: exactly what a glTF 2.0 viewer replays for a rotation sampler with
// interpolation CUBICSPLINE — the cubic Hermite spline of the quaternion's four
// components, normalized (glTF 2.0 §3.11 and Appendix C):
//   p(s) = (2s³ − 3s² + 1)·qₖ + Δ(s³ − 2s² + s)·bₖ + (−2s³ + 3s²)·qₖ₊₁ + Δ(s³ − s²)·aₖ₊₁,
//   q(s) = p(s)/|p(s)|,  s = (t − tₖ)/Δ, Δ = tₖ₊₁ − tₖ,
// with bₖ the out-tangent of key k and aₖ₊₁ the in-tangent of key k+1, in units per
// second. The keys are sign-aligned first (qₖ·qₖ₋₁ ≥ 0), as written to a file.
//
// The tangents are ours: one per key (aₖ = bₖ = mₖ, so the curve is C¹), the
// derivative of the unit quaternion for the angular velocity ωₖ that the `clamped`
// method uses at that key — mₖ = ½·ω̃ₖ·qₖ (fixed frame), ωₖ Steffen's limited parabola
// of the two neighbouring secant rates (zero where they point apart: holds, stops,
// reversals), the end segment's secant rate at the ends. Hence:
//  * holds stay exactly still (equal keys, zero tangents: p is the key itself);
//  * C¹ (p is C¹ and never 0 on a segment whose keys are less than 180° apart:
//    |p| ≥ the chord's distance from the origin minus the tangent terms, which the
//    limiter keeps small); coordinate-invariant (left or right multiplication of all
//    keys is an orthogonal map of R⁴ that carries the tangents along and commutes
//    with normalization);
//  * not exact on constant angular velocity: the normalized chord of a Hermite
//    cubic is not the geodesic (measured on a constant spin: 2e-7° off at 10° per
//    key, 4e-5° at 30°, 1.3e-3° at 60°).
// gltf_cubic_keys gives the keys and tangents that a CUBICSPLINE sampler stores, so
// a writer puts in the file exactly the curve this interpolator evaluates.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rotinterp {

// What a CUBICSPLINE rotation sampler holds for a track: the sign-aligned unit keys
// and one tangent per key (dq/dt, components x, y, z, w as Quat::coeffs(), per second).
struct GltfCubicKeys {
  std::vector<double> times;
  std::vector<Quat> keys;
  std::vector<Eigen::Vector4d> tangents;
};

// The keys and tangents of `track` (rules 1–3 of RotationTrack; signs are aligned here).
Result<GltfCubicKeys> gltf_cubic_keys(RotationTrack track);

// glTF's CUBICSPLINE rotation at s ∈ [0, 1] of a segment of length dt: the Hermite
// cubic of the components, normalized (a zero p — which our tangents never give —
// returns q0).
Quat gltf_cubic_segment(const Quat& q0, const Eigen::Vector4d& b0, const Quat& q1, const Eigen::Vector4d& a1, double dt,
                        double s);

Result<std::unique_ptr<Interpolator>> make_gltf_cubic(RotationTrack track);

}  // namespace rotinterp
