// slerp against Eigen's Quaternion::slerp, and where Eigen's formula is fragile.
#include "support.h"

#include "rotinterp/interp/nlerp.h"
#include "rotinterp/core/slerp_kernel.h"
#include "rotinterp/interp/slerp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rotinterp {
namespace {

using test::random_quat;
using test::random_unit;

TEST(Slerp, MatchesEigenSlerpWhereEigenIsAccurate) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const Quat a = random_quat(rng);
    const double angle = 1e-3 + (3.1 - 1e-3) * u(rng);  // rad, away from 0 and π
    Quat b = apply_moving(a, RotVec(random_unit(rng) * angle));
    if (u(rng) < 0.5) b.coeffs() *= -1.0;  // either stored sign: both take the short way
    const double t = u(rng);
    worst = std::max(worst, angular_distance(slerp(a, b, t), a.slerp(t, b)));
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(Slerp, AKeyWithItselfIsThatKeyEvenWhenItsDotIsOneUlpAboveOne) {
  // The key (1, 2, 3, 4)/√30 to 8 digits. Normalized with Eigen it has q·q = 1 − 1 ulp
  // here; nudging z up by ulps gives a key whose q·q rounds above 1.
  Quat q = Quat(0.18257419, 0.36514837, 0.54772256, 0.73029674).normalized();
  for (int k = 0; k < 16 && !(q.dot(q) > 1.0); ++k) q.z() = std::nextafter(q.z(), 2.0);
  ASSERT_GT(q.dot(q), 1.0);               // the fixture: above 1 by rounding …
  ASSERT_TRUE(std::isnan(std::acos(q.dot(q))));  // … where acos-based slerp gives NaN
  for (double t : {0.0, 0.3, 0.5, 1.0}) {
    const Quat s = slerp(q, q, t);
    EXPECT_LT((s.coeffs() - q.coeffs()).norm(), 1e-15) << t;
    EXPECT_NEAR(s.norm(), 1.0, 1e-15);
    const Quat e = q.slerp(t, q);
    std::printf("[ info ] Eigen slerp(q, q, %.1f): finite %d, |q| − 1 = %.2g\n", t, e.coeffs().allFinite(),
                e.norm() - 1.0);
  }
}

TEST(Slerp, KeysOneNanoradianApartGiveAngleTTimesIt) {
  std::mt19937_64 rng(2);
  double eigen_worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Quat a = random_quat(rng);
    const Vec3 axis = random_unit(rng);
    const Quat b = apply_moving(a, RotVec(axis * 1e-9));
    for (double t : {0.25, 0.5, 0.75, 0.9}) {
      const Vec3 d = log(a.conjugate() * slerp(a, b, t)).vec();
      EXPECT_NEAR(d.norm(), t * 1e-9, 1e-6 * t * 1e-9) << i << " " << t;
      EXPECT_LT((d.normalized() - axis).norm(), 1e-6);
      const Vec3 e = log(a.conjugate() * a.slerp(t, b).normalized()).vec();
      eigen_worst = std::max(eigen_worst, std::abs(e.norm() - t * 1e-9) / (t * 1e-9));
    }
  }
  RecordProperty("eigen_relative_error", std::to_string(eigen_worst));
  std::printf("[ info ] Eigen slerp, keys 1e-9 rad apart: angle off by up to %.2g relative\n", eigen_worst);
}

TEST(Slerp, StaysUnitAndOnTheGeodesicAcrossAllAngles) {
  std::mt19937_64 rng(3);
  for (double angle : {0.0, 1e-300, 1e-15, 1e-12, 1e-6, 1e-3, 1.0, 3.0, 3.14159, kPi}) {
    const Quat a = random_quat(rng);
    const Vec3 axis = random_unit(rng);
    const Quat b = apply_moving(a, RotVec(axis * angle));
    for (double t : {0.0, 0.1, 0.5, 0.99, 1.0}) {
      const Quat s = slerp(a, b, t);
      ASSERT_TRUE(s.coeffs().allFinite());
      EXPECT_NEAR(s.norm(), 1.0, 1e-15);
      EXPECT_LT(angular_distance(s, apply_moving(a, RotVec(axis * (t * angle)))), 1e-15 + 1e-14 * angle)
          << angle << " " << t;
    }
  }
}

TEST(Nlerp, IsOnTheGeodesicButNotConstantSpeed) {
  const Quat a = Quat::Identity(), b = test::Rz(kPi / 2);
  const Quat m = nlerp(a, b, 0.25);
  EXPECT_LT(std::hypot(m.x(), m.y()), 1e-15);
  const double angle = angular_distance(a, m);
  EXPECT_GT(std::abs(angle - kPi / 8), 1e-3);  // 0.25 of the way in t, not in angle
  EXPECT_LT(angular_distance(nlerp(a, b, 0.5), slerp(a, b, 0.5)), 1e-15);
}

TEST(SlerpMethod, SamplesThroughThePolynomialKernelWithinItsBound) {
  // Non-uniform key times, steps from 0.01° to 170° (stored in either hemisphere),
  // and sample times repeated, unsorted and outside the keys: batch and single
  // evaluation are the kernel (core/slerp_kernel.h) — within 1e-15 of it where it is
  // 1e-8 from the exact slerp — and within kSlerpKernelMaxError of the exact slerp.
  std::mt19937_64 rng(21);
  const double deg = kPi / 180;
  const double steps[] = {0.01 * deg, 3 * deg, 30 * deg, 170 * deg, 90 * deg, 1e-9};
  RotationTrack track;
  Quat q = random_quat(rng);
  double t = 0.0;
  for (double step : steps) {
    track.times.push_back(t);
    track.keys.push_back(track.keys.size() % 2 ? Quat(-q.coeffs()) : q);
    q = apply_moving(q, RotVec(random_unit(rng) * step));
    t += 0.01 + step;
  }
  track.times.push_back(t);
  track.keys.push_back(q);
  auto f = make_slerp(track);
  ASSERT_TRUE(f);
  std::vector<double> at = {-1.0, t + 1.0, 0.5 * t, 0.5 * t};
  std::uniform_real_distribution<double> u(0.0, t);
  for (int s = 0; s < 500; ++s) at.push_back(u(rng));
  std::vector<Quat> out(at.size());
  (*f)->evaluate(at.data(), at.size(), out.data());
  double worst = 0.0;
  for (std::size_t j = 0; j < at.size(); ++j) {
    const double x = std::clamp(at[j], 0.0, t);
    const std::size_t i = static_cast<std::size_t>(
        std::min<std::ptrdiff_t>(std::upper_bound(track.times.begin(), track.times.end(), x) - track.times.begin() - 1,
                                 static_cast<std::ptrdiff_t>(track.times.size()) - 2));
    const double v = (x - track.times[i]) / (track.times[i + 1] - track.times[i]);
    const Quat a = track.keys[i], b = align_pair(a, track.keys[i + 1]);
    const Quat expected = v <= 0.0 ? a : v >= 1.0 ? b : slerp_poly(a, b, v);
    EXPECT_LT(angular_distance(out[j], expected), 1e-15) << at[j];
    EXPECT_LT(angular_distance(out[j], (*f)->evaluate(at[j])), 1e-15) << at[j];
    EXPECT_NEAR(out[j].norm(), 1.0, 1e-14);
    worst = std::max(worst, angular_distance(out[j], slerp(a, b, v)));
  }
  EXPECT_LE(worst, kSlerpKernelMaxError);
}

}  // namespace
}  // namespace rotinterp
