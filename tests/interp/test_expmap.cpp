// expmap: the nearest-branch unwrapping is what makes long spins exact.
#include "support.h"

#include "rotinterp/interp/expmap.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {
namespace {

// A spin from the identity at 2 rad/s for 6 s: 12 rad, almost two turns, keys
// every 0.4 s (0.8 rad apart), sampled off the keys.
RotationTrack spin(const Vec3& omega) {
  std::vector<double> times;
  for (int k = 0; k <= 15; ++k) times.push_back(0.4 * k);
  return test::constant_velocity_track(omega, Quat::Identity(), times);
}

double worst_error(const Interpolator& p, const Vec3& omega) {
  double worst = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    const double x = 1e-4 + (6.0 - 2e-4) * k / 1000;  // off the keys, inside the range
    worst = std::max(worst, angular_distance(p.evaluate(x), exp(RotVec(omega * x))));
  }
  return worst;
}

TEST(Expmap, IsExactForASpinFromTheIdentityPastTwoPi) {
  const Vec3 omega = Vec3(1, -2, 0.5).normalized() * 2.0;
  for (auto spline : {ExpmapOptions::Spline::catmull_rom, ExpmapOptions::Spline::natural}) {
    ExpmapOptions o;
    o.spline = spline;
    auto p = make_expmap(spin(omega), o);
    ASSERT_TRUE(p);
    EXPECT_LT(worst_error(**p, omega), 1e-12);
    EXPECT_LT(((*p)->angular_velocity(4.1) - omega).norm(), 1e-12);
  }
}

TEST(Expmap, FailsOnTheSameSpinWithoutUnwrapping) {
  const Vec3 omega = Vec3(1, -2, 0.5).normalized() * 2.0;
  ExpmapOptions o;
  o.unwrap = false;
  auto p = make_expmap(spin(omega), o);
  ASSERT_TRUE(p);
  const double worst = worst_error(**p, omega);
  EXPECT_GT(worst, 0.5);  // rad: the principal logs jump by 2π at every half turn
  std::printf("[ info ] expmap without unwrapping: %.2f rad off on a 12 rad spin\n", worst);
}

TEST(Expmap, RelativeToTheMeanPassesTheKeysAndCutsTheCoordinateDependence) {
  const RotationTrack track = test::random_track(61, 8, 0.6, 0.2, 0.4);
  std::mt19937_64 rng(4);
  const Quat R = test::random_quat(rng);
  RotationTrack moved = track;
  for (Quat& q : moved.keys) q = R * q;
  ExpmapOptions plain, rel;
  rel.relative_to_mean = true;
  double deviation[2] = {0.0, 0.0};
  int i = 0;
  for (const ExpmapOptions& o : {plain, rel}) {
    auto p = make_expmap(track, o);
    auto m = make_expmap(moved, o);
    ASSERT_TRUE(p && m);
    for (std::size_t k = 0; k < track.keys.size(); ++k)
      EXPECT_LT(angular_distance((*p)->evaluate(track.times[k]), track.keys[k]), 1e-9);
    for (int s = 0; s <= 400; ++s) {
      const double x = track.times.front() + (track.times.back() - track.times.front()) * s / 400.0;
      deviation[i] = std::max(deviation[i], angular_distance(R * (*p)->evaluate(x), (*m)->evaluate(x)));
    }
    ++i;
  }
  // Taken relative to the (left-equivariant) mean, a left rotation of all keys
  // moves the curve alike; the plain version does not.
  EXPECT_LT(deviation[1], 1e-9);
  EXPECT_GT(deviation[0], 1e-6);
  std::printf("[ info ] expmap left-invariance deviation: plain %.3g rad, relative to mean %.3g rad\n", deviation[0],
              deviation[1]);
}

TEST(Expmap, IsNotCoordinateInvariantASpinFromAPose70DegreesOffTheIdentityIsMissedByUpTo32Degrees) {
  // The example the README gives: a spin about a fixed (world) axis at 55° per key,
  // starting from a pose 70° about x from the identity. The invariant methods that
  // are exact on constant angular velocity follow it exactly; expmap interpolates
  // rotation vectors measured from the identity and leaves the spin — by 12.1°
  // when the spin axis is perpendicular to x, by 31.6° when it is 45° from x.
  const Quat q0 = exp(RotVec(Vec3(1, 0, 0) * (70.0 * kPi / 180)));
  std::vector<double> times;
  for (int k = 0; k <= 8; ++k) times.push_back(k);
  for (const auto& [axis, expected] : {std::pair{Vec3(0, 0, 1), 12.1}, std::pair{Vec3(1, 1, 0).normalized(), 31.6}}) {
    const Vec3 omega = axis * (55.0 * kPi / 180);  // rad per key (1 s apart)
    const RotationTrack track = test::constant_velocity_track(omega, q0, times);
    auto worst_of = [&](const std::string& method) {
      auto p = make_interpolator(method, track).value();
      double worst = 0.0;
      for (int s = 0; s <= 800; ++s) {
        const double x = s / 100.0;
        worst = std::max(worst, angular_distance(p->evaluate(x), integrate_angular_velocity(q0, omega, x)));
      }
      return worst * 180 / kPi;
    };
    const double expmap = worst_of("expmap");
    std::printf("[ info ] spin 55°/key about (%.2f, %.2f, %.2f) from 70° about x: expmap misses it by %.1f°\n",
                axis.x(), axis.y(), axis.z(), expmap);
    EXPECT_NEAR(expmap, expected, 0.1);
    for (const char* exact : {"slerp", "squad", "c2", "bf", "clamped"}) EXPECT_LT(worst_of(exact), 1e-7) << exact;
  }
}

}  // namespace
}  // namespace rotinterp
