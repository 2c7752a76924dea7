// Curves continued at their end velocity (interp/continued.h), over every method it
// takes: the keys' range untouched, a free spin at the end key's velocity beyond it,
// orientation and velocity continuous across the end keys, never NaN.
#include "support.h"

#include "rotinterp/interp/continued.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace rotinterp {
namespace {

using test::random_track;

std::vector<std::string> continued_names() {
  std::vector<std::string> n;
  for (const MethodInfo& m : methods())
    if (can_continue(m)) n.push_back(m.name);
  return n;
}

std::unique_ptr<Interpolator> curve_of(const std::string& method, const RotationTrack& keys) {
  auto r = make_interpolator(method, keys);
  EXPECT_TRUE(r) << r.error();
  return std::move(*r);
}

class Continued : public ::testing::TestWithParam<std::string> {};

TEST_P(Continued, HoldsTheCurveInsideAndSpinsAtTheEndVelocityBeyond) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const RotationTrack keys = random_track(seed, 7, 2.5, 0.01, 0.2);  // steps up to 143°
    const double t0 = keys.times.front(), tn = keys.times.back();
    const auto base = curve_of(GetParam(), keys);
    const auto f = continue_at_end_velocity(curve_of(GetParam(), keys), t0, tn);
    for (int i = 0; i <= 50; ++i) {
      const double t = i == 50 ? tn : t0 + (tn - t0) * i / 50.0;
      ASSERT_EQ(f->evaluate(t).coeffs(), base->evaluate(t).coeffs()) << t;
    }
    const std::size_t k = keys.times.size();
    const double first_dt = keys.times[1] - t0, last_dt = tn - keys.times[k - 2];
    for (const auto& [end, out, dt_key] : {std::tuple{tn, 1.0, last_dt}, std::tuple{t0, -1.0, first_dt}}) {
      const Vec3 w = base->angular_velocity(end);
      for (double dt : {1e-6, 0.05, 1.0, 40.0}) {
        const double t = end + out * dt;
        const Quat want = exp(RotVec(w * (out * dt))) * base->evaluate(end);
        EXPECT_LT(angular_distance(f->evaluate(t), want), 1e-12) << "seed " << seed << " t " << t;
        EXPECT_EQ(f->angular_velocity(t), w);
        EXPECT_EQ(f->angular_acceleration(t), Vec3::Zero());
      }
      // C¹ across the end key: the one-sided velocities from both sides agree (steps of
      // 1e-4 of the end segment: the O(h²) error of the quotient stays below 1e-8 of ω).
      const double h = 1e-4 * dt_key;
      const Vec3 from_inside = test::one_sided_velocity(*f, end, -out * h);
      const Vec3 from_outside = test::one_sided_velocity(*f, end, out * h);
      EXPECT_LT((from_inside - from_outside).norm(), 1e-5 * (1.0 + w.norm())) << "seed " << seed;
    }
  }
}

TEST_P(Continued, BatchEvaluationMatchesOneAtATimeAndNeverGivesNaN) {
  const RotationTrack keys = random_track(9, 6, 3.1, 0.02, 0.1);  // steps near 178°
  const double t0 = keys.times.front(), tn = keys.times.back();
  const auto f = continue_at_end_velocity(curve_of(GetParam(), keys), t0, tn);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> times = {t0 - 5.0, t0, 0.5 * (t0 + tn), tn, tn + 1e-9, tn + 1e6, inf, -inf, nan};
  std::vector<Quat> batch(times.size());
  f->evaluate(times.data(), times.size(), batch.data());
  for (std::size_t i = 0; i < times.size(); ++i) {
    ASSERT_TRUE(batch[i].coeffs().allFinite()) << times[i];
    EXPECT_NEAR(batch[i].norm(), 1.0, 1e-12);
    EXPECT_EQ(batch[i].coeffs(), f->evaluate(times[i]).coeffs()) << times[i];
    EXPECT_TRUE(f->angular_velocity(times[i]).allFinite());
  }
}

TEST_P(Continued, OneKeyStaysStill) {
  const RotationTrack one{{0.5}, {test::Rz(1.0)}};
  const auto f = continue_at_end_velocity(curve_of(GetParam(), one), 0.5, 0.5);
  EXPECT_LT(angular_distance(f->evaluate(9.0), test::Rz(1.0)), 1e-15);
  EXPECT_EQ(f->angular_velocity(9.0), Vec3::Zero());
}

INSTANTIATE_TEST_SUITE_P(Methods, Continued, ::testing::ValuesIn(continued_names()), test::method_test_name);

TEST(Continued, TakesTheMethodsWithAVelocityAtTheirKeys) {
  EXPECT_EQ(continued_method_names(), "squad, expmap, bf, c2, expmap-c2, clamped, gltf-cubic");
}

}  // namespace
}  // namespace rotinterp
