// bf: the spherical cubic B-spline of Buss and Fillmore (ACM TOG 20(2), 2001)
// interpolating the keys; every point a weighted average (core/average.h).
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/average.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <memory>
#include <vector>

namespace rotinterp {

// ---- the spline ------------------------------------------------------------------------
//
// A cubic B-spline with knots at the key times (extended past both ends by
// reflection: t₋ⱼ = 2t₀ − tⱼ, tₙ₊ⱼ = 2tₙ − tₙ₋ⱼ), every point the BF average of the
// four active control points with the B-spline basis values as weights. The
// control points c₀…cₙ are solved so that the curve passes through the keys; the
// phantom end points are reflections c₋₁ = c₀c₁⁻¹c₀, cₙ₊₁ = cₙcₙ₋₁⁻¹cₙ (flat
// analogue: natural end conditions). C², coordinate-invariant, exact on constant
// angular velocity at any key spacing (B-splines reproduce linear motion along a
// geodesic).
struct BfSplineOptions {
  enum class Solver {
    // BF's S1 fixed point: cⱼ ← exp(log(qⱼ pⱼ⁻¹))·cⱼ, pⱼ the curve at tⱼ.
    s1,
    // Newton on the same equations: the corrections solve the block-tridiagonal
    // system of the exact Jacobian of the key misses (implicit differentiation
    // of the averages), with step halving; quadratic convergence.
    newton,
  };
  Solver solver = Solver::newton;
  // Converged when every key is missed by less than this (rad).
  double tolerance = 1e-13;
  int max_iterations = 1000;  // S1 needs hundreds on widely spaced keys; Newton < 10
  // Largest angle (rad) between neighbouring knots. The four control points of a
  // span must lie in one open hemisphere of S³, and interpolating control points
  // overshoot the keys, so neighbours far apart (≳ 80°, and every 180° pair) have
  // no BF spline through them. Segments whose keys are further apart than this get
  // evenly spaced in-between knots on the c2 curve through the keys (C², h⁴, so
  // wide steps keep the spline's accuracy; on the geodesic they were no better
  // than slerp). An interval more than 3 times as long as a neighbouring one is
  // graded with in-between knots too (1e-6 s next to 1e4 s has no BF spline
  // either: the control points would leave the hemisphere); there, and wherever
  // the c2 knots do not converge, the knots lie on the geodesics (slerp) and the
  // step is halved (up to 3 times) until the control points converge. The curve
  // passes through every original key and stays C², bi-invariant and exact on
  // constant angular velocity (c2 and slerp are, and the knots lie on them).
  // Default 60°.
  double max_key_step = kPi / 3.0;
  BfAverageOptions average;   // for every curve point
};

// Errors: invalid track; control points that do not converge to 1e-9 rad even at
// the finest refinement (not seen in the test suite, which includes 10⁶
// adversarial key pairs).
Result<std::unique_ptr<Interpolator>> make_bf(RotationTrack track, const BfSplineOptions& options = {});

}  // namespace rotinterp
