// The Buss–Fillmore weighted average and spline.
#include "support.h"

#include "rotinterp/interp/bf.h"
#include "rotinterp/interp/c2.h"
#include "rotinterp/interp/slerp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace rotinterp {
namespace {

using test::random_quat;
using test::random_unit;
using Algorithm = BfAverageOptions::Algorithm;

Vec3 stationarity(const Quat& m, const std::vector<Quat>& q, const std::vector<double>& w) {
  Vec3 g = Vec3::Zero();
  double total = 0.0;
  for (double x : w) total += x;
  for (std::size_t i = 0; i < q.size(); ++i) g += (w[i] / total) * log(m.conjugate() * q[i]).vec();
  return g;
}

TEST(BfAverage, OfTwoPointsIsTheirSlerp) {
  std::mt19937_64 rng(1);
  for (double angle : {1e-9, 0.1, 1.0, 2.0, 3.0}) {
    const Quat a = random_quat(rng), b = apply_moving(a, RotVec(random_unit(rng) * angle));
    for (double t : {0.1, 0.25, 0.5, 0.8})
      for (Algorithm alg : {Algorithm::a1, Algorithm::a2}) {
        BfAverageOptions o;
        o.algorithm = alg;
        auto m = bf_average({a, b}, {1 - t, t}, o);
        ASSERT_TRUE(m) << m.error();
        EXPECT_LT(angular_distance(*m, slerp(a, b, t)), 1e-12) << angle << " " << t;
      }
  }
}

TEST(BfAverage, IsStationaryToTheRoundOffFloor) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Quat c = random_quat(rng);
    std::vector<Quat> q;
    std::vector<double> w;
    for (int i = 0; i < 6; ++i) {
      q.push_back(apply_moving(c, RotVec(random_unit(rng) * (1.4 * u(rng)))));  // up to 80° off
      if (u(rng) < 0.5) q.back().coeffs() *= -1.0;
      w.push_back(u(rng));
    }
    for (Algorithm alg : {Algorithm::a1, Algorithm::a2}) {
      BfAverageOptions o;
      o.algorithm = alg;
      auto m = bf_average(q, w, o);
      ASSERT_TRUE(m) << m.error();
      EXPECT_LT(stationarity(*m, q, w).norm(), 1e-12) << trial;
    }
  }
}

TEST(BfAverage, IsBiInvariant) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Quat c = random_quat(rng), R = random_quat(rng), S = random_quat(rng);
    std::vector<Quat> q, moved;
    std::vector<double> w;
    for (int i = 0; i < 5; ++i) {
      q.push_back(apply_moving(c, RotVec(random_unit(rng) * (1.2 * u(rng)))));
      moved.push_back(R * q.back() * S);
      w.push_back(0.1 + u(rng));
    }
    auto a = bf_average(q, w), b = bf_average(moved, w);
    ASSERT_TRUE(a && b);
    EXPECT_LT(angular_distance(R * *a * S, *b), 1e-12);
  }
}

TEST(BfAverage, DiffersFromTheChordalMeanFor120DegreesApart_30Versus19p1) {
  const Quat a = Quat::Identity(), b = test::rot(Vec3(1, 1, 0), 2.0 * kPi / 3.0);
  auto m = bf_average({a, b}, {0.75, 0.25});
  ASSERT_TRUE(m);
  const Quat c = chordal_mean({a, b}, {0.75, 0.25});
  const double deg = 180.0 / kPi;
  EXPECT_NEAR(angular_distance(a, *m) * deg, 30.0, 1e-9);
  EXPECT_NEAR(angular_distance(a, c) * deg, 19.1, 0.05);
  // On the same geodesic, just at the wrong place.
  EXPECT_LT(angular_distance(c, slerp(a, b, angular_distance(a, c) / (2.0 * kPi / 3.0))), 1e-12);
}

TEST(BfAverage, AgreesWithTheChordalMeanOnATightCluster) {
  std::mt19937_64 rng(4);
  const Quat c = random_quat(rng);
  std::vector<Quat> q;
  std::vector<double> w;
  for (int i = 0; i < 8; ++i) {
    q.push_back(apply_moving(c, RotVec(random_unit(rng) * 0.01)));
    w.push_back(1.0 + i);
  }
  auto m = bf_average(q, w);
  ASSERT_TRUE(m);
  EXPECT_LT(angular_distance(*m, chordal_mean(q, w)), 1e-6);  // differ at O(spread³)
}

TEST(BfAverage, RejectsBadWeightsAndHalfTurnPairs) {
  const Quat a = Quat::Identity(), b = test::Rz(0.5);
  auto neg = bf_average({a, b}, {1.5, -0.5});
  ASSERT_FALSE(neg);
  EXPECT_NE(neg.error().find("negative"), std::string::npos);
  EXPECT_FALSE(bf_average({a, b}, {0.5}));
  EXPECT_FALSE(bf_average({a, b}, {0.0, 0.0}));
  EXPECT_FALSE(bf_average({}, {}));
  EXPECT_FALSE(bf_average({a, Quat(0, 0, 0, 0)}, {0.5, 0.5}));
  EXPECT_FALSE(bf_average({a, b}, {std::nan(""), 0.5}));
  // Half a turn apart: two equally good means (±90° about the axis).
  auto half = bf_average({a, Quat(0, 1, 0, 0)}, {0.5, 0.5});
  ASSERT_FALSE(half);
  EXPECT_NE(half.error().find("hemisphere"), std::string::npos);
  // Zero weights are ignored, weights need not sum to 1.
  auto z = bf_average({a, b, Quat(0, 1, 0, 0)}, {2.0, 2.0, 0.0});
  ASSERT_TRUE(z);
  EXPECT_LT(angular_distance(*z, test::Rz(0.25)), 1e-14);
}

TEST(BfSpline, S1AndNewtonSolversGiveTheSameCurve) {
  const RotationTrack track = test::random_track(71, 9, 0.7, 0.1, 0.4);
  BfSplineOptions s1;
  s1.solver = BfSplineOptions::Solver::s1;
  auto a = make_bf(track, s1);
  auto b = make_bf(track);
  ASSERT_TRUE(a && b);
  for (int s = 0; s <= 300; ++s) {
    const double x = track.times.front() + (track.times.back() - track.times.front()) * s / 300.0;
    EXPECT_LT(angular_distance((*a)->evaluate(x), (*b)->evaluate(x)), 1e-11) << x;
  }
}

TEST(BfSpline, AndC2AreBothC2AndCloseOnSmoothKeys) {
  const RotationTrack track = test::random_track(73, 12, 0.5, 0.1, 0.3);
  auto bf = make_bf(track);
  auto c2 = make_c2(track);
  ASSERT_TRUE(bf && c2);
  double worst = 0.0;
  for (int s = 0; s <= 1000; ++s) {
    const double x = track.times.front() + (track.times.back() - track.times.front()) * s / 1000.0;
    worst = std::max(worst, angular_distance((*bf)->evaluate(x), (*c2)->evaluate(x)));
  }
  // Different C² interpolants of the same keys (both exact on constant angular
  // velocity): they agree to a fraction of the key spacing.
  EXPECT_LT(worst, 0.05);
  RecordProperty("bf_vs_c2_max_rad", std::to_string(worst));
  std::printf("[ info ] bf vs c2 on 0.5-rad key steps: max %.3g rad apart\n", worst);
}

TEST(BfSpline, GradesIntervalsWhoseRatioPassesDoublePrecision) {
  // fuzz_interp crash-860848d6: half turns between keys whose neighbouring intervals
  // differ by 1e97. Grading used to place each new knot at a fraction of the long
  // interval, which rounds to its end once the ratio passes 2⁵³, so no knot was
  // added and the control points could not converge. Here scaled to ratios 1e10 …
  // 1e97, plus the fuzzer's own times.
  const Quat half_z(0.0, 0.0, 0.0, -1.0), half_yz(0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5));
  std::vector<std::vector<double>> times = {{-1.1389096839582165e-88, -2.3534373660385329e-185, 0.0}};
  for (double small : {1e-10, 1e-16, 1e-20, 1e-50, 1e-97}) times.push_back({-1.0, -small, 0.0});
  for (const std::vector<double>& t : times) {
    RotationTrack track;
    track.times = t;
    track.keys = {half_z, Quat(-1.0, 0.0, 0.0, 0.0), half_yz};
    auto bf = make_bf(track);
    ASSERT_TRUE(bf) << t[1] << ": " << bf.error();
    for (std::size_t k = 0; k < t.size(); ++k)
      EXPECT_LT(angular_distance((*bf)->evaluate(t[k]), track.keys[k]), 1e-9) << t[1] << " key " << k;
    for (int s = 0; s <= 64; ++s) {
      const Quat q = (*bf)->evaluate(t[0] + (t[2] - t[0]) * s / 64.0);
      ASSERT_TRUE(q.coeffs().allFinite()) << t[1];
      EXPECT_NEAR(q.norm(), 1.0, 1e-12) << t[1];
    }
  }
}

TEST(BfSpline, KeysADenormalTimeApartGiveFiniteUnitPoints) {
  // fuzz_interp crash-a17e74bf: keys 3.4e-310 s apart. The B-spline weights overflow
  // to inf and NaN there; the averages' start must stay finite (the chordal sum
  // divided by its infinite norm was NaN, and the iteration kept it).
  RotationTrack track;
  track.times = {0.0, 3.4055437702490903e-310};
  track.keys = {Quat::Identity(), Quat(0.5, 0.5, 0.5, 0.5)};
  auto bf = make_bf(track);
  ASSERT_TRUE(bf) << bf.error();
  for (int s = -2; s <= 34; ++s) {
    const Quat q = (*bf)->evaluate(track.times[1] * s / 32.0);
    ASSERT_TRUE(q.coeffs().allFinite()) << s;
    EXPECT_NEAR(q.norm(), 1.0, 1e-12) << s;
  }
}

TEST(BfSpline, IsTheSameCurveWhenItsTimesAreScaledIntoSubnormals) {
  // fuzz_interp timeout-c600b3bd: keys 1.3e-321 s apart. The B-spline weights on
  // subnormal spans overflowed to inf and NaN, the curve there was the averages'
  // fallback, and the solve crawled (167 Newton steps, 0.37 s). The spline depends
  // only on ratios of times: times scaled by 2⁻¹⁰⁰⁰ (exact) give the same curve.
  const Quat half_z(0.0, 0.0, 0.0, -1.0), half_yz(0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5));
  RotationTrack normal;
  normal.times = {-1.0, -std::ldexp(1.0, -30), 0.0};
  normal.keys = {half_z, Quat(-1.0, 0.0, 0.0, 0.0), half_yz};
  RotationTrack subnormal = normal;
  for (double& t : subnormal.times) t = std::ldexp(t, -1000);
  ASSERT_LT(-subnormal.times[1], std::numeric_limits<double>::min());
  auto a = make_bf(normal), b = make_bf(subnormal);
  ASSERT_TRUE(a) << a.error();
  ASSERT_TRUE(b) << b.error();
  for (double t : {-1.0, -0.5, -1e-3, -1e-6, -std::ldexp(1.0, -29), -std::ldexp(1.5, -30), -std::ldexp(1.0, -30),
                   -std::ldexp(0.5, -30), -std::ldexp(0.1, -30), 0.0})
    EXPECT_LT(angular_distance((*a)->evaluate(t), (*b)->evaluate(std::ldexp(t, -1000))), 1e-9) << t;
}

TEST(BfSpline, KeepsC2AccuracyOnKeyStepsWiderThanItsKnotLimit) {
  // A smooth motion sampled so that keys are 60–80° apart: every segment gets
  // in-between knots. On the geodesic they made bf no better than slerp (RMS
  // 0.94°); on the c2 curve bf keeps c2's accuracy.
  auto truth = [](double t) {
    return exp(RotVec(1.4 * t, 0.6 * std::sin(1.3 * t), 0.4 * std::cos(0.7 * t))) *
           exp(RotVec(0.3 * std::sin(0.9 * t), 0.0, 0.2 * t));
  };
  RotationTrack track;
  for (int k = 0; k <= 12; ++k) {
    track.times.push_back(k);
    track.keys.push_back(truth(k));
  }
  double widest = 0.0, narrowest = kPi;
  for (std::size_t k = 1; k < track.keys.size(); ++k) {
    widest = std::max(widest, angular_distance(track.keys[k - 1], track.keys[k]));
    narrowest = std::min(narrowest, angular_distance(track.keys[k - 1], track.keys[k]));
  }
  ASSERT_GT(narrowest, BfSplineOptions{}.max_key_step);  // every segment is refined
  auto rms = [&](const Interpolator& p) {
    double sum = 0.0;
    int n = 0;
    for (int s = 100; s <= 1100; ++s, ++n) {  // interior: away from the end conditions
      const double e = angular_distance(p.evaluate(s / 100.0), truth(s / 100.0));
      sum += e * e;
    }
    return std::sqrt(sum / n) * 180 / kPi;
  };
  const double bf = rms(*make_bf(track).value()), c2 = rms(*make_c2(track).value()),
               sl = rms(*make_slerp(track).value());
  std::printf("[ info ] key steps %.0f–%.0f°: RMS bf %.3f°, c2 %.3f°, slerp %.3f°\n", narrowest * 180 / kPi,
              widest * 180 / kPi, bf, c2, sl);
  EXPECT_LT(bf, 1.5 * c2);
  EXPECT_LT(bf, 0.3 * sl);
}

}  // namespace
}  // namespace rotinterp
