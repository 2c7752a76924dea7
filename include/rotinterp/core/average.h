// Weighted averages of orientations: the Buss–Fillmore spherical weighted average
// (ACM TOG 20(2), 2001) and Markley's chordal mean. Conventions as in rotation.h.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace rotinterp {

// ---- the Buss–Fillmore average ------------------------------------------------------
//
// The orientation m minimizing Σ wᵢ·dist(m, qᵢ)², i.e. the solution of the
// stationarity condition Σ wᵢ·log(m⁻¹qᵢ) = 0. Bi-invariant:
// avg(R·qᵢ·S) = R·avg(qᵢ)·S.
struct BfAverageOptions {
  enum class Algorithm {
    a1,  // BF's A1 fixed point m ← m·exp(Σ wᵢ log(m⁻¹qᵢ)): linear convergence
    a2,  // Newton on the same equation: m ← m·exp(H⁻¹g), H = Σ wᵢ J_l⁻¹(log(m⁻¹qᵢ));
         // falls back to an A1 step when H is near singular or the residual grows
  };
  Algorithm algorithm = Algorithm::a2;
  // Converged when |Σ wᵢ log(m⁻¹qᵢ)| (rad) is below `tolerance` …
  double tolerance = 1e-15;
  // … or below `stall_tolerance` once round-off stops it decreasing.
  double stall_tolerance = 1e-13;
  int max_iterations = 200;
};

// Errors: sizes differ or are zero; a weight is negative or not finite; the
// weights sum to zero; a quaternion is zero or not finite; the inputs do not fit
// in an open hemisphere; no convergence within max_iterations.
// Inputs are orientations: each is taken as ±qᵢ in the hemisphere of the heaviest
// input (BF's algorithm needs the points in an open hemisphere of S³). An input
// exactly 180° from the heaviest one (dot 0) lies on that hemisphere's border —
// its two signs are equally near and the mean is not unique — and is refused, as
// is a result 180° from an input. Weights are divided by their sum; zero-weight
// inputs are ignored. Starts from the normalized weighted sum (the chordal
// estimate) and iterates until converged. The iteration uses BF's log on S³ (the
// signs as aligned, angles up to 2π), which equals the SO(3) log for every input
// within 180° of the mean — then Σ wᵢ·log(m⁻¹qᵢ) = 0 holds with the core log too.
Result<Quat> bf_average(const std::vector<Quat>& q, const std::vector<double>& w, const BfAverageOptions& options = {});

// Markley's chordal mean: the unit eigenvector of Σ wᵢ·qᵢqᵢᵀ with the largest
// eigenvalue (minimizes Σ wᵢ·|m ∓ qᵢ|², not the geodesic distances): close to the
// BF mean for tight clusters, far off for spread ones (keys 120° apart with weights
// 0.75/0.25: 19.1° from the first instead of 30°). Same weight rules, no errors:
// invalid input gives the identity.
Quat chordal_mean(const std::vector<Quat>& q, const std::vector<double>& w);

// ---- for splines whose every point is an average ---------------------------------------

// BF's log on S³ (not on SO(3)): the tangent vector at 1 toward q along the great
// circle, as a rotation vector (angle 2·atan2(|v|, w) ∈ [0, 2π]). Unlike the core
// log it does not pick the nearer sign of q, so averages of points spread over
// more than 180° of rotation (still in one open hemisphere of S³) stay smooth.
// Every curve point averages nearby control points, so nearly all calls take the
// first branch: 2·atan(x)/s = (2/w)·atan(x)/x with x² = |v|²/w², no square root
// (half_angle's series, for angles below 2·atan(1/8) ≈ 14°). Always inlined: it is
// the body of the average's loop.
[[gnu::always_inline]] inline Vec3 log_s3(const Quat& q) {
  const Vec3 v = q.vec();
  const double w = q.w(), s2 = v.squaredNorm();
  if (w > 0.0 && s2 <= (1.0 / 64.0) * w * w) return v * angle_over_sine_series(s2, w);
  const double s = std::sqrt(s2);
  if (!(s > 0.0)) return Vec3::Zero();
  return v * (2.0 * half_angle(s, w) / s);
}

// The BF average of n unit points p with positive weights w summing to 1, the signs
// as given (the caller keeps them in one open hemisphere), without bf_average's
// checks: from the chordal estimate (the normalized weighted sum, or p[1] where
// that is zero or not finite — weights overflow on knots a denormal time apart),
// iterated as `options` say. A Newton step from a residual below 1e-6 rad is the
// last one (it lands within ~1e-15 rad of the mean). n ≥ 2.
Quat bf_average_of_points(const Quat* p, const double* w, int n, const BfAverageOptions& options);

}  // namespace rotinterp
