// Error metrics between a reference motion and a rebuilt one: the building blocks
// of `rotinterp eval`. Eigen and the core only; no file formats, no threads.
//
// Units: angles in radians, angular velocity in rad/s, angular acceleration in
// rad/s², distances in clip units (the caller converts for reports).
//
// What is measured, per joint:
//  * the geodesic angle between reference and rebuilt orientation
//    (rotinterp::angular_distance — atan2 form, exact near 0);
//  * its split into swing and twist about the joint's bone axis: the error
//    rotation e = q_ref⁻¹·q_test (in the joint's own frame) is factored as
//    e = swing·twist (core swing_twist), twist about the bone axis;
//  * world-space position error of every joint and End Site by forward kinematics;
//  * the ACL "virtual vertex" (shell) error: points at distance d along each of the
//    joint's local x, y, z axes, carried to object space by the joint's world
//    transform; per sample the largest of the three displacements;
//  * smoothness of a rebuilt curve: RMS angular acceleration from uniform samples,
//    and the largest jump of angular velocity and of angular acceleration at keys.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace rotinterp {

// Default shell (virtual vertex) distance: 3 cm, ACL's default for characters.
constexpr double kDefaultShellDistanceMetres = 0.03;

// ---- statistics -----------------------------------------------------------------

// Summary of a set of non-negative errors. All zero for an empty set.
struct ErrorStats {
  std::size_t count = 0;
  double mean = 0.0;
  double rms = 0.0;
  double p95 = 0.0;  // 95th percentile, see percentile()
  double max = 0.0;
};

// The p-th quantile (p in [0, 1]) of values[0..n): linear interpolation between the
// order statistics at rank p·(n − 1) (NumPy's default, Hyndman–Fan type 7). Reorders
// `values`. 0 for n = 0; non-finite entries are read as 0 (none should reach here).
double percentile(double* values, std::size_t n, double p);
// count, mean, RMS, p95 and max of values[0..n); reorders `values`.
ErrorStats error_stats(double* values, std::size_t n);

// A running RMS/max/mean without storing the samples (for position errors, where no
// percentile is reported).
struct RunningError {
  std::size_t count = 0;
  double sum = 0.0;
  double sum_sq = 0.0;
  double max = 0.0;

  void add(double e) {
    ++count;
    sum += e;
    sum_sq += e * e;
    if (e > max) max = e;
  }
  double mean() const;
  double rms() const;
};

// ---- skeleton geometry ------------------------------------------------------------

// rest_pose(), skeleton_height() and in_clip_units() are in clip/clip.h.

// ---- rotation error of one joint ----------------------------------------------------

struct RotationError {
  ErrorStats angle;    // geodesic angle between reference and test, rad
  RunningError swing;  // swing part of the error rotation, rad (no percentile needed)
  RunningError twist;  // twist part about the bone axis, rad
};

// Compares ref[i] with test[i] for i < n. `bone_axis` is in the joint's frame (see
// bone_axes()). `scratch` is reused between calls to avoid allocation. Without
// `swing_twist` only the angle is measured (swing and twist stay empty).
RotationError rotation_error(const Quat* ref, const Quat* test, std::size_t n, const Vec3& bone_axis,
                             std::vector<double>& scratch, bool swing_twist = true);

// ---- position and shell error ----------------------------------------------------------

// The shell (virtual vertex) error of one joint between two world poses: the
// vertices p + R·(d·eₐ) move by ΔP + d·(R_ref − R_test)·eₐ, the columns of the
// difference of the two rotation matrices; the largest of the three. eval's
// metrics and reduce's budget both measure with it.
inline double shell_error(const Quat& r_ref, const Vec3& p_ref, const Quat& r_test, const Vec3& p_test, double d) {
  const Mat3 dr = d * (r_ref.toRotationMatrix() - r_test.toRotationMatrix());
  const Vec3 dp = p_ref - p_test;
  double worst = 0.0;
  for (int a = 0; a < 3; ++a) worst = std::max(worst, (dp + dr.col(a)).squaredNorm());
  return std::sqrt(worst);
}

// Accumulators over the samples of a clip, one per joint / End Site.
struct PoseError {
  std::vector<RunningError> joint_position;     // |p_ref − p_test| of each joint
  std::vector<RunningError> end_site_position;  // |p_ref − p_test| of each End Site
  std::vector<RunningError> joint_shell;        // virtual-vertex error of each joint
};

// Empty accumulators sized for `skeleton`.
PoseError make_pose_error(const Skeleton& skeleton);
// Adds one sample: two world poses of the same skeleton (forward_kinematics output).
// `shell_distance` in clip units (> 0).
void accumulate_pose_error(const WorldPose& ref, const WorldPose& test, double shell_distance, PoseError& acc);
// Adds one sample whose two poses are equal (every error 0) without computing them:
// at the keys of a method that reproduces them bit for bit.
void accumulate_equal_poses(PoseError& acc);

// ---- smoothness -------------------------------------------------------------------------

struct Smoothness {
  double acceleration_rms = 0.0;  // rad/s²
  double acceleration_max = 0.0;  // rad/s²
};

// From n samples q[0..n) uniformly spaced by dt > 0: ω_k = log(q_{k+1} q_k⁻¹)/dt (fixed
// frame), α_k = (ω_{k+1} − ω_k)/dt; RMS and max of |α_k| over the n − 2 values. Zero
// for n < 3 or dt ≤ 0.
Smoothness sampled_smoothness(const Quat* q, std::size_t n, double dt);

struct KeyJumps {
  double velocity = 0.0;      // largest |ω(t_k⁺) − ω(t_k⁻)| over interior keys, rad/s
  double acceleration = 0.0;  // largest |α(t_k⁺) − α(t_k⁻)| over interior keys, rad/s²
};

// Relative step of the one-sided differences at a key: h = kKeyJumpStep times the
// shorter adjacent key interval. Small enough that the O(h²·jerk) bias of the
// extrapolated one-sided velocity stays far below any real jump, large enough that
// double round-off in the curve (ε ≈ 1e-16) adds only ~ε/h² to the second
// differences: 1e-6 rad/s² for a 10 ms key interval.
constexpr double kKeyJumpStep = 1e-3;

// The jumps of `curve`'s angular velocity and acceleration at the interior keys
// key_times[1..n−2] (sorted, strictly increasing): one-sided differences at steps
// h, 2h on each side, the velocity extrapolated to the key to second order. A C¹
// curve reads ~0 velocity jump, a C² curve ~0 acceleration jump. `at_keys`, if
// given, holds curve.evaluate(key_times[i]) for every key (a caller that sampled
// the curve there already): the stencils then skip their centres.
KeyJumps key_jumps(const Interpolator& curve, const std::vector<double>& key_times, const Quat* at_keys = nullptr);

// The jumps between two one-sided stencils of step h > 0: `before` at t − 2h, t − h, t
// and `after` at t', t' + h, t' + 2h (t' = t at a key; at a cycle's seam t is the
// end of one period and t' the start of the next, eval/seam.h). key_jumps' rule.
KeyJumps one_sided_jumps(const Quat before[3], const Quat after[3], double h);

}  // namespace rotinterp
