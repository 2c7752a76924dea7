// Shared fixtures for the interpolator tests: key tracks, random rotations and
// numerical derivatives of a curve.
#pragma once

#include "rotinterp/interp/interpolator.h"
#include "support/random_rotations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace rotinterp::test {

inline Quat rot(const Vec3& axis, double angle) { return exp(RotVec::from_axis_angle(axis, angle)); }
inline Quat Rz(double angle) { return rot(Vec3::UnitZ(), angle); }

// Keys from a random walk: each step turns about a random axis by step(rng) rad
// and lasts interval(rng) s.
template <class Step, class Interval>
RotationTrack random_walk_track(std::uint64_t seed, int n, Step step, Interval interval) {
  std::mt19937_64 rng(seed);
  RotationTrack t;
  double time = 0.25;
  Quat q = random_quat(rng);
  for (int k = 0; k < n; ++k) {
    t.times.push_back(time);
    t.keys.push_back(q);
    time += interval(rng);
    q = apply_moving(q, RotVec(random_unit(rng) * step(rng)));
  }
  return t;
}

// A "motion capture like" track: random steps of up to `max_step` rad between
// keys, non-uniform times with intervals in [dt_min, dt_max].
inline RotationTrack random_track(std::uint64_t seed, int n, double max_step, double dt_min, double dt_max) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return random_walk_track(
      seed, n, [&](std::mt19937_64& rng) { return max_step * (0.3 + 0.7 * u(rng)); },
      [&](std::mt19937_64& rng) { return dt_min + (dt_max - dt_min) * u(rng); });
}

// Constant angular velocity: q(t) = exp(ω t)·q₀ at the given key times.
inline RotationTrack constant_velocity_track(const Vec3& omega, const Quat& q0, const std::vector<double>& times) {
  RotationTrack t;
  t.times = times;
  for (double x : times) t.keys.push_back(integrate_angular_velocity(q0, omega, x));
  return t;
}

// x(s) = log(q(t + s)·q(t)⁻¹): the fixed-frame displacement from q(t). x′(0) = ω(t)
// and x″(0) = ω̇(t) (the commutator term of second order vanishes).
inline Vec3 displacement(const Interpolator& f, double t, double s) {
  return displacement_fixed(f.evaluate(t), f.evaluate(t + s)).vec();
}

// One-sided derivatives at t from the side sign(h) (h ≠ 0): angular velocity with
// error O(h²), angular acceleration with error O(h³).
inline Vec3 one_sided_velocity(const Interpolator& f, double t, double h) {
  const Vec3 x1 = displacement(f, t, h), x2 = displacement(f, t, 2 * h);
  return (4.0 * x1 - x2) / (2.0 * h);
}
inline Vec3 one_sided_acceleration(const Interpolator& f, double t, double h) {
  const Vec3 x1 = displacement(f, t, h), x2 = displacement(f, t, 2 * h), x3 = displacement(f, t, 3 * h),
             x4 = displacement(f, t, 4 * h);
  // f″(0) from f(0) = 0, f(h) … f(4h): (−104f₁ + 114f₂ − 56f₃ + 11f₄)/(12h²).
  return (-104.0 * x1 + 114.0 * x2 - 56.0 * x3 + 11.0 * x4) / (12.0 * h * h);
}
// Central angular velocity at t (inside a segment).
inline Vec3 central_velocity(const Interpolator& f, double t, double h) {
  return displacement_fixed(f.evaluate(t - h), f.evaluate(t + h)).vec() / (2.0 * h);
}

// Every registered method's name, for the suites instantiated over all of them.
inline std::vector<std::string> all_method_names() {
  std::vector<std::string> n;
  for (const MethodInfo& m : methods()) n.push_back(m.name);
  return n;
}

// A method's name as a test name ('-' is not allowed in one).
inline std::string method_test_name(const ::testing::TestParamInfo<std::string>& i) {
  std::string s = i.param;
  std::replace(s.begin(), s.end(), '-', '_');
  return s;
}

}  // namespace rotinterp::test
