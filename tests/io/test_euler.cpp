// Euler decomposition for the writer: every valid axis sequence reconstructs the
// orientation, and the solution nearest the previous angles follows a motion
// through ±180° and through gimbal lock without jumps.
#include "rotinterp/io/files/euler.h"

#include <gtest/gtest.h>

#include <random>

namespace rotinterp {
namespace {

std::vector<EulerAxes> all_sequences() {
  std::vector<EulerAxes> out;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        if (a != b && b != c) out.push_back({a, b, c});
  return out;
}

TEST(Euler, EveryValidSequenceReconstructsRandomOrientations) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  const auto seqs = all_sequences();
  ASSERT_EQ(seqs.size(), 12u);
  for (const EulerAxes& axes : seqs)
    for (int i = 0; i < 500; ++i) {
      const Quat q = Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
      const Vec3 prev(g(rng) * 3, g(rng) * 3, g(rng) * 3);
      const Vec3 e = euler_nearest(q, axes, prev);
      ASSERT_LE(angular_distance(euler_to_quat(axes, e), q), 1e-12);
    }
}

TEST(Euler, GimbalLockOrientationsReconstructAndKeepTheFirstAngle) {
  for (const EulerAxes& axes : all_sequences()) {
    const bool proper = axes[0] == axes[2];
    const double middle = proper ? 0.0 : kPi / 2;  // the locked middle angle
    const Quat q = euler_to_quat(axes, Vec3(0.4, middle, -0.9));
    const Vec3 prev(0.1, middle, 0.0);
    const Vec3 e = euler_nearest(q, axes, prev);
    EXPECT_LE(angular_distance(euler_to_quat(axes, e), q), 1e-12);
    EXPECT_DOUBLE_EQ(e[0], prev[0]);
  }
}

TEST(Euler, NearestSolutionFollowsSpinsPast180WithoutWraps) {
  for (const EulerAxes& axes : all_sequences()) {
    Vec3 prev = Vec3::Zero();
    for (int k = 0; k <= 400; ++k) {
      // A smooth motion whose angles run far past ±180°.
      const Vec3 truth(0.02 * k, 0.4 * std::sin(0.01 * k) + (axes[0] == axes[2] ? 0.8 : 0.0), -0.03 * k);
      const Vec3 e = euler_nearest(euler_to_quat(axes, truth), axes, prev);
      if (k > 0) {
        ASSERT_LE((e - prev).cwiseAbs().maxCoeff(), 0.05) << "step " << k;
      }
      prev = e;
    }
  }
}

TEST(Euler, ParsesOrdersCaseInsensitivelyAndRejectsInvalidOnes) {
  EXPECT_EQ(parse_euler_order("ZXY"), (EulerAxes{2, 0, 1}));
  EXPECT_EQ(parse_euler_order("xyz"), (EulerAxes{0, 1, 2}));
  EXPECT_EQ(parse_euler_order("ZYZ"), (EulerAxes{2, 1, 2}));
  EXPECT_FALSE(parse_euler_order("XXY"));
  EXPECT_FALSE(parse_euler_order("XY"));
  EXPECT_FALSE(parse_euler_order("XYW"));
}

}  // namespace
}  // namespace rotinterp
