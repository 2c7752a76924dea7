// The polynomial slerp kernel against the exact slerp of core/geodesic.h: within
// its stated bound on any pair, exact to round-off on the steps its short tiers
// serve, unit, finite, and the same value, bit for bit, whichever block a sample is in.
#include "rotinterp/core/geodesic.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/core/slerp_kernel.h"

#include "support/random_rotations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace rotinterp;

namespace {

struct Pairs {
  std::vector<Quat> a, b;
  std::vector<double> t;
};

using test::random_quat;
using test::random_unit;

// a random, b = a rotated by `angle` (rad, a rotation angle in [0, 2π)) about a
// random axis, stored in either hemisphere; t in [t_lo, t_hi].
void add_pair(Pairs& p, std::mt19937_64& rng, double angle, double t_lo, double t_hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Quat a = random_quat(rng);
  Quat b = apply_moving(a, RotVec(random_unit(rng) * angle));
  if (u(rng) < 0.5) b.coeffs() *= -1.0;  // antipodal storage: the same orientation
  p.a.push_back(a);
  p.b.push_back(b);
  p.t.push_back(t_lo + (t_hi - t_lo) * u(rng));
}

// The kernel over all pairs at once (blocks mixing every tier).
std::vector<Quat> kernel(const Pairs& p) {
  const std::size_t n = p.a.size();
  std::vector<double> c(12 * n);
  double* col[12];
  for (int k = 0; k < 12; ++k) col[k] = c.data() + k * n;
  for (std::size_t j = 0; j < n; ++j) {
    col[0][j] = p.a[j].w(), col[1][j] = p.a[j].x(), col[2][j] = p.a[j].y(), col[3][j] = p.a[j].z();
    col[4][j] = p.b[j].w(), col[5][j] = p.b[j].x(), col[6][j] = p.b[j].y(), col[7][j] = p.b[j].z();
  }
  slerp_arrays({col[0], col[1], col[2], col[3]}, {col[4], col[5], col[6], col[7]}, p.t.data(), n,
               {col[8], col[9], col[10], col[11]});
  std::vector<Quat> out(n);
  for (std::size_t j = 0; j < n; ++j) out[j] = Quat(col[8][j], col[9][j], col[10][j], col[11][j]);
  return out;
}

// Largest rotation angle between kernel and exact slerp; each result also unit and finite.
double worst_error(const Pairs& p) {
  const std::vector<Quat> got = kernel(p);
  double worst = 0.0;
  for (std::size_t j = 0; j < got.size(); ++j) {
    EXPECT_TRUE(got[j].coeffs().allFinite()) << j;
    EXPECT_NEAR(got[j].norm(), 1.0, 1e-14) << j;
    worst = std::max(worst, angular_distance(got[j], slerp(p.a[j], p.b[j], p.t[j])));
  }
  return worst;
}

TEST(SlerpKernel, StaysWithinItsBoundOfTheExactSlerpAtEveryAngle) {
  std::mt19937_64 rng(49);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Pairs p;
  const double near_pi[] = {1e-12, 1e-9, 1e-6, 1e-3, 0.1};
  for (int s = 0; s < 20000; ++s) {
    add_pair(p, rng, kTwoPi * u(rng), -0.1, 1.1);                   // any angle, t a little outside [0, 1]
    add_pair(p, rng, std::pow(10.0, -12.0 * u(rng)), 0.0, 1.0);     // θ near 0
    add_pair(p, rng, kPi - near_pi[s % 5] * u(rng), -0.1, 1.1);     // θ near 180°, either side
    add_pair(p, rng, kPi + near_pi[s % 5] * u(rng), 0.0, 1.0);
  }
  for (double t : {0.0, 1.0, 0.5, -0.1, 1.1})
    for (double angle : {0.0, 1e-300, 1.0, 3.0, kPi - 1e-9}) add_pair(p, rng, angle, t, t);
  const double worst = worst_error(p);
  std::printf("[ info ] slerp kernel: largest error %.3g rad over %zu pairs (bound %.0e)\n", worst, p.a.size(),
              kSlerpKernelMaxError);
  RecordProperty("largest_error_rad", std::to_string(worst));
  EXPECT_LE(worst, kSlerpKernelMaxError);
}

TEST(SlerpKernel, ShortTiersAreExactToRoundOffOnTheStepsTheyServe) {
  // Rotations up to 33.7° take 4 or 8 terms, whose truncation is below 2e-17 rad.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Pairs p;
  for (int s = 0; s < 20000; ++s) add_pair(p, rng, (s % 2 ? 0.14 : 0.58) * u(rng), -0.1, 1.1);
  EXPECT_LT(worst_error(p), 2e-15);
}

TEST(SlerpKernel, GivesASampleTheSameValueWhicheverBlockItIsIn) {
  // Alone (4 terms), and in a block where a 170° step takes all 16.
  std::mt19937_64 rng(11);
  Pairs alone, mixed;
  for (int s = 0; s < 63; ++s) add_pair(alone, rng, 0.01 * (s + 1) / 63.0, 0.0, 1.0);
  mixed = alone;
  add_pair(mixed, rng, 170.0 * kPi / 180.0, 0.0, 1.0);
  const std::vector<Quat> a = kernel(alone), m = kernel(mixed);
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_EQ(a[j].coeffs(), m[j].coeffs()) << j;
    const Quat one = slerp_poly(alone.a[j], alone.b[j], alone.t[j]);
    EXPECT_EQ(one.coeffs(), a[j].coeffs()) << j;
  }
}

TEST(SlerpKernel, NeverGivesNaNOnTheHardPairs) {
  const Quat i(0, 1, 0, 0), j(0, 0, 1, 0), one = Quat::Identity();
  const Quat tiny(1e-12, 1.0, 0.0, 0.0), minus_one(-1, 0, 0, 0);
  const std::pair<Quat, Quat> pairs[] = {{one, one},  {one, minus_one}, {i, j},          {i, Quat(0, -1, 0, 0)},
                                         {one, tiny}, {tiny, i},        {minus_one, tiny}};
  for (const auto& [a, b] : pairs)
    for (double t : {0.0, 1e-300, 0.25, 0.5, 1.0, -0.1, 1.1}) {
      const Quat r = slerp_poly(a.normalized(), b.normalized(), t);
      ASSERT_TRUE(r.coeffs().allFinite()) << t;
      EXPECT_NEAR(r.norm(), 1.0, 1e-14);
      // a·b = 0 (i, j): a half turn, both ways equal; elsewhere the exact slerp.
      if (a.dot(b) != 0.0) {
        EXPECT_LE(angular_distance(r, slerp(a.normalized(), b.normalized(), t)), kSlerpKernelMaxError);
      }
    }
}

TEST(SlerpKernel, SeriesIsExactlyTheLinearWeightsAtZeroAngle) {
  // d = 0: f(t) = t with no division; the endpoints are exact for every tier.
  EXPECT_EQ(slerp_weight<4>(0.3, 0.0), 0.3);
  EXPECT_EQ(slerp_weight<kSlerpTerms>(0.3, 0.0), 0.3);
  for (double d : {-1.0, -0.5, -1e-3, 0.0}) {
    EXPECT_EQ(slerp_weight<kSlerpTerms>(0.0, d), 0.0) << d;
    EXPECT_EQ(slerp_weight<kSlerpTerms>(1.0, d), 1.0) << d;
  }
}

}  // namespace
