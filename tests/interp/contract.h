// What the contract tests share (test_contract.cpp, test_contract_wide_steps.cpp):
// the contract's tolerances, the hard fixtures, and the Contract suite's fixture.
#pragma once

#include "support.h"

#include "rotinterp/core/slerp_kernel.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::test {

// Passing through the keys: the promise of interpolator.h.
inline constexpr double kKeyTolerance = 1e-9;  // rad
// Unit output: |‖q‖ − 1| below this (a few ulps of accumulated round-off).
inline constexpr double kUnitTolerance = 1e-12;
// Coordinate invariance where a method claims it (rad).
inline constexpr double kInvarianceTolerance = 1e-9;

// How close a method's curve comes to a closed form it claims to follow, at best
// `tolerance`: slerp samples by the polynomial kernel, exact to round-off for
// rotations up to 83° between keys and within kSlerpKernelMaxError beyond.
inline double curve_tolerance(const std::string& method, double tolerance) {
  return method == "slerp" ? std::max(tolerance, kSlerpKernelMaxError) : tolerance;
}

struct Fixture {
  std::string name;
  RotationTrack track;
};

inline RotationTrack make(std::vector<double> t, std::vector<Quat> q) {
  RotationTrack r;
  r.times = std::move(t);
  r.keys = std::move(q);
  return r;
}

// The adversarial tracks (keys in whatever hemisphere they come).
inline std::vector<Fixture> hard_fixtures() {
  std::mt19937_64 rng(7);
  const Quat a = random_quat(rng);
  const Quat ma(-a.w(), -a.x(), -a.y(), -a.z());
  const Quat i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1);
  const Vec3 axis = test::random_unit(rng);
  std::vector<Fixture> f;
  f.push_back({"random", random_track(11, 12, 1.0, 0.1, 0.5)});
  f.push_back({"identical", make({0, 1, 2, 3, 4}, {a, a, a, a, a})});
  f.push_back({"antipodal", make({0, 1, 2, 3}, {a, ma, a, ma})});
  f.push_back({"half_turns", make({0, 1, 2, 3}, {Quat::Identity(), i, k, Quat(0, 0, 0, -1) * i})});
  f.push_back({"half_turns_rotated", make({0, 0.5, 1.5, 2}, {a, a * i, a * i * j, a * i * j * k})});
  f.push_back({"1e-12_apart", make({0, 1, 2, 3}, {a, apply_moving(a, RotVec(axis * 1e-12)),
                                                  apply_moving(a, RotVec(axis * 2e-12)), a})});
  RotationTrack extreme = random_track(13, 6, 0.8, 1.0, 1.0);
  extreme.times = {0.0, 1e-6, 1e4, 1e4 + 1e-6, 2e4, 2e4 + 1e-6};
  f.push_back({"extreme_intervals", extreme});
  RotationTrack tiny = random_track(17, 5, 0.5, 1e-6, 1e-6);
  f.push_back({"1e-6_s_intervals", tiny});
  RotationTrack huge = random_track(19, 5, 0.5, 1e4, 1e4);
  f.push_back({"1e4_s_intervals", huge});
  f.push_back({"one_key", make({3.0}, {a})});
  f.push_back({"two_keys", make({-1.0, 2.0}, {a, apply_moving(a, RotVec(axis * 2.0))})});
  // Neighbours stored 338° apart (dot −0.981): really 22.1°.
  f.push_back({"338_degrees_as_stored", make({0, 1, 2}, {Rz(0.0), Quat(-Rz(0.3857).coeffs()), Rz(0.7714)})});
  return f;
}

inline std::vector<double> dense_times(const RotationTrack& t, int per_segment) {
  std::vector<double> out;
  out.push_back(t.times.front() - 1.0);
  for (std::size_t k = 0; k + 1 < t.times.size(); ++k)
    for (int s = 0; s < per_segment; ++s)
      out.push_back(t.times[k] + (t.times[k + 1] - t.times[k]) * (static_cast<double>(s) / per_segment));
  out.push_back(t.times.back());
  out.push_back(t.times.back() + 1.0);
  return out;
}

inline std::unique_ptr<Interpolator> build(const MethodInfo& m, const RotationTrack& t) {
  auto r = m.make(t);
  if (!r) {
    ADD_FAILURE() << m.name << ": " << r.error();
    return nullptr;
  }
  return std::move(*r);
}

// Parameterized by a method's name; instantiated over methods() in test_contract.cpp.
class Contract : public ::testing::TestWithParam<std::string> {
 protected:
  const MethodInfo& method() const { return *find_method(GetParam()); }
};

}  // namespace rotinterp::test
