#include "rotinterp/clip/translation_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace rotinterp;

namespace {

TranslationTrack track(std::vector<double> times, std::vector<Vec3> keys) {
  TranslationTrack t;
  t.times = std::move(times);
  t.keys = std::move(keys);
  EXPECT_TRUE(t.validate().ok());
  return t;
}

TranslationTrack random_track(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<double> step(0.01, 0.5), value(-10.0, 10.0);
  TranslationTrack t;
  double time = -0.3;
  for (std::size_t i = 0; i < n; ++i) {
    t.times.push_back(time);
    t.keys.emplace_back(value(rng), value(rng), value(rng));
    time += step(rng);
  }
  return t;
}

}  // namespace

TEST(TranslationCurve, StraightLineAtConstantSpeedIsReproducedExactly) {
  // Non-uniform key times on a line p(t) = p0 + v·t.
  const Vec3 p0(12.5, 90.0, -3.0), v(110.0, 0.0, 47.0);
  std::vector<double> times = {0.0, 0.1, 0.15, 0.5, 0.51, 1.2, 2.0};
  std::vector<Vec3> keys;
  for (double t : times) keys.push_back(p0 + v * t);
  const TranslationTrack tr = track(times, keys);
  for (TranslationInterp m : {TranslationInterp::linear, TranslationInterp::cubic}) {
    const TranslationCurve c(tr, m);
    for (int k = 0; k <= 2000; ++k) {
      const double t = k / 1000.0;
      EXPECT_LE((c.evaluate(t) - (p0 + v * t)).norm(), 1e-12 * (p0 + v * t).norm()) << translation_interp_name(m) << " t=" << t;
      EXPECT_LE((c.derivative(t) - v).norm(), 1e-9 * v.norm()) << translation_interp_name(m) << " t=" << t;
    }
  }
}

TEST(TranslationCurve, BothMethodsPassThroughEveryKeyAndClampOutside) {
  std::mt19937 rng(3);
  const TranslationTrack tr = random_track(rng, 20);
  for (TranslationInterp m : {TranslationInterp::linear, TranslationInterp::cubic}) {
    const TranslationCurve c(tr, m);
    for (std::size_t i = 0; i < tr.times.size(); ++i) EXPECT_LE((c.evaluate(tr.times[i]) - tr.keys[i]).norm(), 1e-12);
    EXPECT_EQ(c.evaluate(tr.times.front() - 5.0), tr.keys.front());
    EXPECT_EQ(c.evaluate(tr.times.back() + 5.0), tr.keys.back());
  }
  // One key: constant.
  const TranslationCurve one(track({0.5}, {Vec3(1, 2, 3)}), TranslationInterp::cubic);
  EXPECT_EQ(one.evaluate(-1.0), Vec3(1, 2, 3));
  EXPECT_EQ(one.evaluate(7.0), Vec3(1, 2, 3));
}

TEST(TranslationCurve, CubicIsC1AcrossNonUniformKeys) {
  std::mt19937 rng(5);
  const TranslationTrack tr = random_track(rng, 30);
  const TranslationCurve c(tr, TranslationInterp::cubic);
  for (std::size_t i = 1; i + 1 < tr.times.size(); ++i) {
    const double t = tr.times[i], eps = 1e-12;  // p'' ~ 1e5 here: a C¹ curve jumps by ~2e-7
    const Vec3 left = c.derivative(t - eps), right = c.derivative(t + eps);
    EXPECT_LE((left - right).norm(), 1e-5 * (1.0 + left.norm())) << "key " << i;
  }
  // Linear, for contrast, jumps in velocity at keys.
  const TranslationCurve lin(tr, TranslationInterp::linear);
  double max_jump = 0.0;
  for (std::size_t i = 1; i + 1 < tr.times.size(); ++i)
    max_jump = std::max(max_jump, (lin.derivative(tr.times[i] - 1e-9) - lin.derivative(tr.times[i] + 1e-9)).norm());
  EXPECT_GT(max_jump, 1.0);
}

TEST(TranslationCurve, DerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  const TranslationTrack tr = random_track(rng, 15);
  const TranslationCurve c(tr, TranslationInterp::cubic);
  std::uniform_real_distribution<double> when(tr.times.front() + 1e-3, tr.times.back() - 1e-3);
  for (int k = 0; k < 500; ++k) {
    const double t = when(rng), h = 1e-6;
    const Vec3 fd = (c.evaluate(t + h) - c.evaluate(t - h)) / (2 * h);
    EXPECT_LE((fd - c.derivative(t)).norm(), 1e-4 * (1.0 + fd.norm())) << "t=" << t;
  }
}

TEST(TranslationCurve, CubicNeverOvershootsItsNeighbouringKeys) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    TranslationTrack tr = random_track(rng, 25);
    // A hard stop: the coordinate runs and then holds still.
    for (std::size_t i = 12; i < 25; ++i) tr.keys[i] = tr.keys[11];
    const TranslationCurve c(tr, TranslationInterp::cubic);
    for (std::size_t i = 0; i + 1 < tr.times.size(); ++i)
      for (int s = 1; s < 50; ++s) {
        const double t = tr.times[i] + (tr.times[i + 1] - tr.times[i]) * s / 50.0;
        const Vec3 p = c.evaluate(t);
        for (int d = 0; d < 3; ++d) {
          const double lo = std::min(tr.keys[i][d], tr.keys[i + 1][d]), hi = std::max(tr.keys[i][d], tr.keys[i + 1][d]);
          ASSERT_GE(p[d], lo - 1e-12) << "segment " << i;
          ASSERT_LE(p[d], hi + 1e-12) << "segment " << i;
        }
      }
  }
}

TEST(TranslationCurve, MethodNamesParse) {
  EXPECT_EQ(parse_translation_interp("linear").value(), TranslationInterp::linear);
  EXPECT_EQ(parse_translation_interp("cubic").value(), TranslationInterp::cubic);
  auto bad = parse_translation_interp("spline");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("linear, cubic"), std::string::npos);
}
