// The error metrics between a reference motion and a rebuilt one (clip/metrics.h).
#include "rotinterp/clip/metrics.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

// ---- statistics -------------------------------------------------------------------

double percentile(double* values, std::size_t n, double p) {
  if (n == 0) return 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i])) values[i] = 0.0;
  p = std::clamp(std::isfinite(p) ? p : 1.0, 0.0, 1.0);
  const double rank = p * static_cast<double>(n - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(rank));
  const double frac = rank - static_cast<double>(lo);
  std::nth_element(values, values + lo, values + n);
  const double a = values[lo];
  if (frac == 0.0 || lo + 1 >= n) return a;
  // The next order statistic is the smallest of the upper part.
  const double b = *std::min_element(values + lo + 1, values + n);
  return a + frac * (b - a);
}

ErrorStats error_stats(double* values, std::size_t n) {
  ErrorStats s;
  if (n == 0) return s;
  double sum = 0.0, sum_sq = 0.0, mx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = std::isfinite(values[i]) ? values[i] : 0.0;
    sum += v;
    sum_sq += v * v;
    mx = std::max(mx, v);
  }
  s.count = n;
  s.mean = sum / static_cast<double>(n);
  s.rms = std::sqrt(sum_sq / static_cast<double>(n));
  s.max = mx;
  s.p95 = percentile(values, n, 0.95);
  return s;
}

double RunningError::mean() const { return count ? sum / static_cast<double>(count) : 0.0; }
double RunningError::rms() const { return count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0; }

// ---- skeleton geometry -------------------------------------------------------------

// ---- rotation error -------------------------------------------------------------------

RotationError rotation_error(const Quat* ref, const Quat* test, std::size_t n, const Vec3& bone_axis_in,
                             std::vector<double>& scratch, bool swing_twist) {
  RotationError out;
  scratch.resize(n);
  double* angle = scratch.data();
  const double an = bone_axis_in.norm();
  const bool has_axis = an > 0.0 && std::isfinite(an);
  const Vec3 axis = has_axis ? Vec3(bone_axis_in / an) : Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    // e = q_ref⁻¹·q_test = (w, v), taken with w ≥ 0. Its angle is 2·atan2(|v|, w) —
    // the same number as angular_distance(ref, test), without its normalizations.
    // The twist about the axis is (w, p·axis)/n with p = v·axis, n = √(w² + p²); the
    // swing e·twist⁻¹ has real part n, so its angle is 2·atan2(|v − p·axis|, n).
    // These are the angles of core swing_twist(e, axis), in closed form (tested).
    // All three are ratios, the same for any |e| (both inputs are unit to
    // rounding): e is not normalized; only a zero or non-finite e reads as no error.
    // Equal samples (a key the method reproduces bit for bit) have no error either.
    const Quat e = ref[i].conjugate() * test[i];
    const double en2 = e.coeffs().squaredNorm();
    if (ref[i].coeffs() == test[i].coeffs() || !(en2 > 0.0) || !std::isfinite(en2)) {
      angle[i] = 0.0;
      if (swing_twist) out.swing.add(0.0), out.twist.add(0.0);
      continue;
    }
    double w = e.w();
    Vec3 v = e.vec();
    if (w < 0.0) w = -w, v = -v;
    angle[i] = 2.0 * half_angle(v.norm(), w);
    if (!swing_twist) continue;
    const double p = v.dot(axis);
    const double tw2 = w * w + p * p;
    if (!has_axis || tw2 < kSwingTwistDegenerate * kSwingTwistDegenerate * en2) {
      out.swing.add(angle[i]);  // no axis, or a swing within √ε of 180°: all swing
      out.twist.add(0.0);
    } else {
      out.twist.add(2.0 * half_angle(std::abs(p), w));
      out.swing.add(2.0 * half_angle((v - p * axis).norm(), std::sqrt(tw2)));
    }
  }
  out.angle = error_stats(angle, n);
  return out;
}

// ---- position and shell error ------------------------------------------------------------

PoseError make_pose_error(const Skeleton& skeleton) {
  PoseError acc;
  acc.joint_position.assign(skeleton.joints.size(), RunningError{});
  acc.joint_shell.assign(skeleton.joints.size(), RunningError{});
  acc.end_site_position.assign(skeleton.end_sites.size(), RunningError{});
  return acc;
}

void accumulate_pose_error(const WorldPose& ref, const WorldPose& test, double shell_distance, PoseError& acc) {
  const std::size_t n = std::min({ref.position.size(), test.position.size(), acc.joint_position.size()});
  for (std::size_t j = 0; j < n; ++j) {
    const Vec3 dp = ref.position[j] - test.position[j];
    acc.joint_position[j].add(dp.norm());
    acc.joint_shell[j].add(shell_error(ref.rotation[j], ref.position[j], test.rotation[j], test.position[j], shell_distance));
  }
  const std::size_t m =
      std::min({ref.end_site_position.size(), test.end_site_position.size(), acc.end_site_position.size()});
  for (std::size_t e = 0; e < m; ++e) acc.end_site_position[e].add((ref.end_site_position[e] - test.end_site_position[e]).norm());
}

void accumulate_equal_poses(PoseError& acc) {
  for (std::vector<RunningError>* v : {&acc.joint_position, &acc.joint_shell, &acc.end_site_position})
    for (RunningError& e : *v) e.add(0.0);
}

// ---- smoothness ------------------------------------------------------------------------------

Smoothness sampled_smoothness(const Quat* q, std::size_t n, double dt) {
  Smoothness s;
  if (n < 3 || !(dt > 0.0) || !std::isfinite(dt)) return s;
  // The samples come from an interpolator (unit quaternions): log(q_{k+1} q_k⁻¹)
  // directly, without displacement_fixed's renormalization of both.
  Vec3 prev = log(q[1] * q[0].conjugate()).vec() / dt;
  double sum_sq = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Vec3 w = log(q[k + 1] * q[k].conjugate()).vec() / dt;
    const double a = (w - prev).norm() / dt;
    sum_sq += a * a;
    s.acceleration_max = std::max(s.acceleration_max, a);
    prev = w;
  }
  s.acceleration_rms = std::sqrt(sum_sq / static_cast<double>(n - 2));
  return s;
}

KeyJumps key_jumps(const Interpolator& curve, const std::vector<double>& key_times, const Quat* at_keys) {
  KeyJumps out;
  if (key_times.size() < 3) return out;
  // Five points t − 2h … t + 2h around every interior key (four when the caller
  // has the centres), all in one sorted batch (h is far below half a key interval,
  // so the stencils do not overlap).
  const std::size_t nk = key_times.size() - 2;
  const int per = at_keys ? 4 : 5;
  std::vector<double> times(per * nk), step(nk);
  for (std::size_t k = 0; k < nk; ++k) {
    const double t = key_times[k + 1];
    const double interval = std::min(t - key_times[k], key_times[k + 2] - t);
    const double h = (interval > 0.0 && std::isfinite(interval)) ? kKeyJumpStep * interval : 0.0;
    step[k] = h;
    double* at = &times[per * k];
    for (int i = -2; i <= 2; ++i)
      if (i != 0 || !at_keys) *at++ = t + i * h;
  }
  std::vector<Quat> q(times.size());
  curve.evaluate(times.data(), times.size(), q.data());
  for (std::size_t k = 0; k < nk; ++k) {
    const double h = step[k];
    if (!(h > 0.0)) continue;
    Quat p[5];
    const Quat* got = &q[per * k];
    if (at_keys) {
      p[0] = got[0], p[1] = got[1], p[2] = at_keys[k + 1], p[3] = got[2], p[4] = got[3];
    } else {
      std::copy(got, got + 5, p);
    }
    const KeyJumps at = one_sided_jumps(p, p + 2, h);
    out.velocity = std::max(out.velocity, at.velocity);
    out.acceleration = std::max(out.acceleration, at.acceleration);
  }
  return out;
}

KeyJumps one_sided_jumps(const Quat before[3], const Quat after[3], double h) {
  KeyJumps out;
  if (!(h > 0.0)) return out;
  Vec3 w[4];  // unit samples
  for (int i = 0; i < 2; ++i) w[i] = log(before[i + 1] * before[i].conjugate()).vec() / h;
  for (int i = 0; i < 2; ++i) w[i + 2] = log(after[i + 1] * after[i].conjugate()).vec() / h;
  // w[i] is the mean velocity over its step: the velocity at the step's midpoint to O(h²).
  const Vec3 a_minus = (w[1] - w[0]) / h;
  const Vec3 a_plus = (w[3] - w[2]) / h;
  const Vec3 w_minus = w[1] + 0.5 * h * a_minus;  // extrapolated from t − h/2 to t
  const Vec3 w_plus = w[2] - 0.5 * h * a_plus;    // from t + h/2 back to t
  const double dv = (w_plus - w_minus).norm();
  const double da = (a_plus - a_minus).norm();
  if (std::isfinite(dv)) out.velocity = dv;
  if (std::isfinite(da)) out.acceleration = da;
  return out;
}

}  // namespace rotinterp
