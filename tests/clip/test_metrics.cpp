// Known answers for the error metrics of `rotinterp eval` (clip/metrics.h).
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <utility>
#include <vector>

namespace rotinterp {
namespace {

Quat random_orientation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

Vec3 random_axis(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

// Hard angles: tiny (where 2·acos|dot| reads noise), moderate, near and at π.
const double kAngles[] = {1e-9, 1e-5, 0.01, 0.5, 2.0, 3.1, kPi};

TEST(Metrics, OffsetOfThetaAboutAnyAxisReadsTheta) {
  std::mt19937 rng(7);
  std::vector<double> scratch;
  for (double theta : kAngles) {
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 axis = random_axis(rng);
      std::vector<Quat> ref(50), moving(50), fixed(50);
      for (std::size_t i = 0; i < ref.size(); ++i) {
        ref[i] = random_orientation(rng);
        moving[i] = ref[i] * exp(RotVec::from_axis_angle(axis, theta));
        fixed[i] = exp(RotVec::from_axis_angle(axis, theta)) * ref[i];
      }
      for (const auto* test : {&moving, &fixed}) {
        const RotationError e = rotation_error(ref.data(), test->data(), ref.size(), random_axis(rng), scratch);
        const double tol = 1e-12 * std::max(1.0, theta) + 1e-15;
        EXPECT_NEAR(e.angle.mean, theta, tol * 10) << "theta " << theta;
        EXPECT_NEAR(e.angle.rms, theta, tol * 10);
        EXPECT_NEAR(e.angle.p95, theta, tol * 10);
        EXPECT_NEAR(e.angle.max, theta, tol * 10);
        EXPECT_NEAR(std::abs(e.angle.max - e.angle.mean) / theta, 0.0, 1e-6);  // relative, even at 1e-9
        EXPECT_EQ(e.angle.count, ref.size());
      }
    }
  }
}

TEST(Metrics, IdenticalCurvesReadExactlyZero) {
  std::mt19937 rng(3);
  std::vector<Quat> ref(100);
  for (Quat& q : ref) q = random_orientation(rng);
  std::vector<Quat> flipped = ref;
  for (Quat& q : flipped) q.coeffs() = -q.coeffs();  // q and −q: the same orientation
  std::vector<double> scratch;
  const RotationError e = rotation_error(ref.data(), flipped.data(), ref.size(), Vec3::UnitY(), scratch);
  EXPECT_EQ(e.angle.max, 0.0);
  EXPECT_EQ(e.swing.max, 0.0);
  EXPECT_EQ(e.twist.max, 0.0);
}

// Offsets of every hard angle about an axis chosen from the bone axis; returns, per
// angle, (swing RMS, twist RMS).
template <class AxisFromBone>
std::vector<std::pair<double, double>> split_of_offsets(unsigned seed, AxisFromBone offset_axis) {
  std::mt19937 rng(seed);
  std::vector<double> scratch;
  std::vector<std::pair<double, double>> out;
  for (double theta : kAngles) {
    const Vec3 bone = random_axis(rng);
    const Vec3 axis = offset_axis(bone, random_axis(rng));
    std::vector<Quat> ref(30), test(30);
    for (std::size_t i = 0; i < ref.size(); ++i) {
      ref[i] = random_orientation(rng);
      test[i] = ref[i] * exp(RotVec::from_axis_angle(axis, theta));
    }
    const RotationError e = rotation_error(ref.data(), test.data(), ref.size(), bone, scratch);
    out.emplace_back(e.swing.rms(), e.twist.rms());
  }
  return out;
}

TEST(Metrics, PureTwistAboutTheBoneReadsAsTwistOnly) {
  const auto split = split_of_offsets(11, [](const Vec3& b, const Vec3&) { return b; });
  for (std::size_t k = 0; k < split.size(); ++k) {
    EXPECT_NEAR(split[k].second, kAngles[k], 1e-12) << kAngles[k];
    EXPECT_NEAR(split[k].first, 0.0, 1e-12) << kAngles[k];
  }
}

TEST(Metrics, PureSwingPerpendicularToTheBoneReadsAsSwingOnly) {
  const auto split = split_of_offsets(13, [](const Vec3& b, const Vec3& r) { return Vec3(b.cross(r).normalized()); });
  for (std::size_t k = 0; k < split.size(); ++k) {
    EXPECT_NEAR(split[k].first, kAngles[k], 1e-12) << kAngles[k];
    EXPECT_NEAR(split[k].second, 0.0, 1e-12) << kAngles[k];
  }
}

TEST(Metrics, SwingAfterTwistSplitsIntoBothAngles) {
  std::mt19937 rng(17);
  std::vector<double> scratch;
  const Vec3 bone = Vec3::UnitY();
  const double swing = 0.4, twist = 1.1;
  std::vector<Quat> ref(10), test(10);
  for (std::size_t i = 0; i < ref.size(); ++i) {
    ref[i] = random_orientation(rng);
    test[i] = ref[i] * exp(RotVec(swing, 0, 0)) * exp(RotVec(0, twist, 0));
  }
  const RotationError e = rotation_error(ref.data(), test.data(), ref.size(), bone, scratch);
  EXPECT_NEAR(e.swing.rms(), swing, 1e-12);
  EXPECT_NEAR(e.twist.rms(), twist, 1e-12);
  EXPECT_GT(e.angle.rms, std::max(swing, twist));
  EXPECT_EQ(e.swing.count, ref.size());
}

TEST(Metrics, ClosedFormsAgreeWithAngularDistanceAndCoreSwingTwist) {
  std::mt19937 rng(19);
  std::vector<double> scratch;
  for (int trial = 0; trial < 2000; ++trial) {
    const Quat a = random_orientation(rng);
    // Mostly small and moderate errors, some near 180°.
    const double theta = trial % 10 == 0 ? kPi - 1e-3 * (trial % 7) : 1e-4 * std::pow(10.0, trial % 5);
    const Quat b = a * exp(RotVec::from_axis_angle(random_axis(rng), theta));
    const Vec3 axis = random_axis(rng);
    const RotationError e = rotation_error(&a, &b, 1, axis, scratch);
    EXPECT_NEAR(e.angle.max, angular_distance(a, b), 1e-12);
    const SwingTwist st = swing_twist(a.conjugate() * b, axis);
    EXPECT_NEAR(e.swing.max, angular_distance(st.swing, Quat::Identity()), 1e-9);
    EXPECT_NEAR(e.twist.max, angular_distance(st.twist, Quat::Identity()), 1e-9);
  }
}

TEST(Metrics, StatisticsMatchHandComputedValues) {
  std::vector<double> v;
  for (int i = 1; i <= 100; ++i) v.push_back(101 - i);  // 100 … 1, unsorted on purpose
  const ErrorStats s = error_stats(v.data(), v.size());
  EXPECT_EQ(s.count, 100u);
  EXPECT_DOUBLE_EQ(s.mean, 50.5);
  EXPECT_DOUBLE_EQ(s.rms, std::sqrt(338350.0 / 100.0));  // Σi² = n(n+1)(2n+1)/6
  EXPECT_DOUBLE_EQ(s.p95, 95.05);                        // numpy.percentile(1..100, 95)
  EXPECT_DOUBLE_EQ(s.max, 100.0);

  std::vector<double> w = {4.0, 3.0};
  const ErrorStats t = error_stats(w.data(), w.size());
  EXPECT_DOUBLE_EQ(t.rms, std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(t.p95, 3.95);

  std::vector<double> three = {3.0, 1.0, 2.0};
  EXPECT_DOUBLE_EQ(percentile(three.data(), 3, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(percentile(three.data(), 3, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(percentile(three.data(), 3, 1.0), 3.0);

  std::vector<double> one = {7.0};
  EXPECT_DOUBLE_EQ(error_stats(one.data(), 1).p95, 7.0);
  const ErrorStats none = error_stats(nullptr, 0);
  EXPECT_EQ(none.count, 0u);
  EXPECT_EQ(none.max, 0.0);

  std::vector<double> bad = {1.0, NAN, INFINITY};
  const ErrorStats b = error_stats(bad.data(), bad.size());
  EXPECT_TRUE(std::isfinite(b.rms) && std::isfinite(b.p95) && std::isfinite(b.mean));
}

TEST(Metrics, RunningErrorMatchesStoredStatistics) {
  RunningError r;
  for (double e : {1.0, 2.0, 2.0}) r.add(e);
  EXPECT_DOUBLE_EQ(r.mean(), 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.rms(), std::sqrt(3.0));
  EXPECT_EQ(r.max, 2.0);
  EXPECT_EQ(RunningError{}.rms(), 0.0);
}

// root at the origin → "upper" 1 unit up y → "lower" 1 unit further, End Site L along z.
Skeleton three_joint_arm(double end_length) {
  Skeleton s;
  s.joints.push_back({"root", -1, Vec3::Zero(), Quat::Identity()});
  s.joints.push_back({"upper", 0, Vec3(0, 1, 0), Quat::Identity()});
  s.joints.push_back({"lower", 1, Vec3(0, 1, 0), Quat::Identity()});
  s.end_sites.push_back({2, Vec3(0, 0, end_length), "EndSite_lower"});
  return s;
}

WorldPose pose_of(const Skeleton& s, const std::vector<Quat>& r) {
  std::vector<Vec3> t;
  for (const Joint& j : s.joints) t.push_back(j.offset);
  WorldPose p;
  forward_kinematics(s, r, t, p);
  return p;
}

TEST(Metrics, KnownBoneRotationMovesTheEndSiteByTheChord) {
  const double length = 0.7, d = 0.03;
  const Skeleton s = three_joint_arm(length);
  ASSERT_TRUE(s.validate().ok());
  for (double theta : {1e-6, 0.3, 1.5, kPi}) {
    const std::vector<Quat> ref(3, Quat::Identity());
    std::vector<Quat> test = ref;
    test[2] = exp(RotVec(theta, 0, 0));  // rotate "lower" about its x axis
    PoseError acc = make_pose_error(s);
    accumulate_pose_error(pose_of(s, ref), pose_of(s, test), d, acc);
    const double chord = 2.0 * length * std::sin(theta / 2);
    EXPECT_NEAR(acc.end_site_position[0].max, chord, 1e-12) << theta;
    EXPECT_NEAR(acc.end_site_position[0].rms(), chord, 1e-12);
    // The rotated joint itself and the joints above do not move.
    for (const RunningError& j : acc.joint_position) EXPECT_NEAR(j.max, 0.0, 1e-15);
    // Shell: the y and z vertices at distance d move by the chord 2·d·sin(θ/2); x stays.
    EXPECT_NEAR(acc.joint_shell[2].max, 2.0 * d * std::sin(theta / 2), 1e-12);
    EXPECT_NEAR(acc.joint_shell[1].max, 0.0, 1e-15);
  }
  // Rotating "upper" by θ about z moves "lower" (1 unit away) by the chord 2·sin(θ/2).
  std::vector<Quat> test(3, Quat::Identity());
  test[1] = exp(RotVec(0, 0, 0.5));
  PoseError acc = make_pose_error(s);
  accumulate_pose_error(pose_of(s, std::vector<Quat>(3, Quat::Identity())), pose_of(s, test), d, acc);
  EXPECT_NEAR(acc.joint_position[2].max, 2.0 * std::sin(0.25), 1e-12);
  EXPECT_NEAR(acc.end_site_position[0].max, 2.0 * std::sin(0.25), 1e-12);  // the End Site lies on the axis
}

TEST(Metrics, EqualPosesCountAsZeroErrorSamples) {
  // The shortcut for poses equal bit for bit gives the accumulators a full
  // comparison gives, mixed with ordinary samples.
  const Skeleton s = three_joint_arm(0.4);
  std::vector<Quat> moved(3, Quat::Identity());
  moved[1] = exp(RotVec(0.2, -0.1, 0.3));
  const WorldPose rest = pose_of(s, std::vector<Quat>(3, Quat::Identity())), bent = pose_of(s, moved);
  PoseError full = make_pose_error(s), quick = make_pose_error(s);
  for (int k = 0; k < 3; ++k) {
    accumulate_pose_error(rest, bent, 0.03, full);
    accumulate_pose_error(rest, bent, 0.03, quick);
    accumulate_pose_error(rest, rest, 0.03, full);
    accumulate_equal_poses(quick);
  }
  auto same = [](const std::vector<RunningError>& a, const std::vector<RunningError>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].count, b[i].count);
      EXPECT_EQ(a[i].sum, b[i].sum);
      EXPECT_EQ(a[i].sum_sq, b[i].sum_sq);
      EXPECT_EQ(a[i].max, b[i].max);
    }
  };
  same(full.joint_position, quick.joint_position);
  same(full.joint_shell, quick.joint_shell);
  same(full.end_site_position, quick.end_site_position);
  EXPECT_EQ(quick.joint_position[2].count, 6u);
  EXPECT_GT(quick.joint_position[2].max, 0.0);
}

TEST(Metrics, BoneAxisPointsToTheLongestChildOrContinuesTheParentBone) {
  Skeleton s = three_joint_arm(0.5);
  s.joints.push_back({"side", 0, Vec3(0.2, 0, 0), Quat::Identity()});   // shorter child of root
  s.joints.push_back({"leaf", 3, Vec3(0, 0, -3), exp(RotVec(0, kPi / 2, 0))});  // no child
  ASSERT_TRUE(s.validate().ok());
  const std::vector<Vec3> axes = bone_axes(s);
  EXPECT_TRUE(axes[0].isApprox(Vec3::UnitY()));  // "upper" (length 1) beats "side" (0.2)
  EXPECT_TRUE(axes[1].isApprox(Vec3::UnitY()));
  EXPECT_TRUE(axes[2].isApprox(Vec3::UnitZ()));  // its End Site
  EXPECT_TRUE(axes[3].isApprox(Vec3(0, 0, -1)));
  // leaf: its own offset (0,0,−1) seen from its frame rotated 90° about y: R⁻¹·(0,0,−1) = (1,0,0).
  EXPECT_NEAR((axes[4] - Vec3(1, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(Metrics, SkeletonHeightIsTheLargestRestExtent) {
  const Skeleton s = three_joint_arm(0.5);
  EXPECT_DOUBLE_EQ(skeleton_height(rest_pose(s)), 2.0);
  Skeleton one;
  one.joints.push_back({"only", -1, Vec3(1, 2, 3), Quat::Identity()});
  EXPECT_EQ(skeleton_height(rest_pose(one)), 0.0);
}

TEST(Metrics, ShellDistanceFollowsTheClipUnits) {
  Clip clip;
  clip.unit.metres_per_unit = 0.01;  // centimetres
  EXPECT_DOUBLE_EQ(in_clip_units(clip, kDefaultShellDistanceMetres), 3.0);
  clip.unit.metres_per_unit = 1.0;
  EXPECT_DOUBLE_EQ(in_clip_units(clip, kDefaultShellDistanceMetres), 0.03);
  clip.unit.metres_per_unit = 0.0;  // not a unit: read as metres
  EXPECT_DOUBLE_EQ(in_clip_units(clip, 0.5), 0.5);
}

TEST(Metrics, ConstantAngularVelocityHasZeroAccelerationAndUniformAccelerationReadsItsValue) {
  const Vec3 axis = Vec3(1, 2, -0.5).normalized();
  const double dt = 1.0 / 120.0;
  std::vector<Quat> constant(200), accelerating(200);
  const double omega = 7.0, alpha = 30.0;
  const Quat q0 = exp(RotVec(0.3, -1.0, 2.0));
  for (std::size_t k = 0; k < constant.size(); ++k) {
    const double t = static_cast<double>(k) * dt;
    constant[k] = exp(RotVec(axis * omega * t)) * q0;
    accelerating[k] = exp(RotVec(axis * 0.5 * alpha * t * t)) * q0;
  }
  const Smoothness c = sampled_smoothness(constant.data(), constant.size(), dt);
  EXPECT_LT(c.acceleration_max, 1e-6);
  const Smoothness a = sampled_smoothness(accelerating.data(), accelerating.size(), dt);
  EXPECT_NEAR(a.acceleration_rms, alpha, 1e-6 * alpha);
  EXPECT_NEAR(a.acceleration_max, alpha, 1e-6 * alpha);
  EXPECT_EQ(sampled_smoothness(constant.data(), 2, dt).acceleration_rms, 0.0);
}

// A curve given by a function of time, for the key-jump known answers.
class FunctionCurve : public Interpolator {
 public:
  explicit FunctionCurve(std::function<Quat(double)> f) : f_(std::move(f)) {}
  Quat evaluate(double t) const override { return f_(t); }
  using Interpolator::evaluate;

 private:
  std::function<Quat(double)> f_;
};

TEST(Metrics, KeyJumpsReadTheVelocityJumpOfAPolylineAndTheAccelerationJumpOfAC1Curve) {
  const Vec3 a1 = Vec3::UnitZ(), a2 = Vec3(1, 1, 0).normalized();
  const double w1 = 2.0, w2 = 5.0, tk = 0.5;
  // Slerp-like: constant ω₁ about a1 until tk, then constant ω₂ about a2.
  const Quat qk = exp(RotVec(a1 * w1 * tk));
  FunctionCurve polyline([&](double t) {
    return t < tk ? exp(RotVec(a1 * w1 * t)) : Quat(exp(RotVec(a2 * w2 * (t - tk))) * qk);
  });
  const KeyJumps p = key_jumps(polyline, {0.0, tk, 1.0});
  EXPECT_NEAR(p.velocity, (a2 * w2 - a1 * w1).norm(), 1e-6);
  EXPECT_LT(p.acceleration, 1e-3);

  // C¹ about one axis: angle = ω·(t − tk) + ½·αᵢ·(t − tk)², α = 3 before, −4 after.
  const double omega = 1.5;
  FunctionCurve c1([&](double t) {
    const double u = t - tk;
    const double alpha = u < 0 ? 3.0 : -4.0;
    return exp(RotVec(a2 * (omega * u + 0.5 * alpha * u * u)));
  });
  const KeyJumps c = key_jumps(c1, {0.0, tk, 1.0});
  EXPECT_LT(c.velocity, 1e-6);
  EXPECT_NEAR(c.acceleration, 7.0, 1e-3);
  EXPECT_EQ(key_jumps(c1, {0.0, 1.0}).velocity, 0.0);  // no interior key
}

TEST(Metrics, KeyJumpsWithTheCurveAtTheKeysGivenAreTheSameNumbers) {
  // evaluate_method passes the samples it has at the keys; for every method the
  // result must be the one key_jumps computes by itself, bit for bit.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(0.05, 0.3), angle(-0.6, 0.6);
  RotationTrack track;
  double t = 0.0;
  Quat q = Quat::Identity();
  for (int k = 0; k < 12; ++k) {
    track.times.push_back(t);
    track.keys.push_back(q);
    t += step(rng);
    q = (q * exp(RotVec(angle(rng), angle(rng), angle(rng)))).normalized();
  }
  for (const MethodInfo& m : methods()) {
    auto curve = make_interpolator(m.name, track);
    ASSERT_TRUE(curve) << m.name;
    std::vector<Quat> at_keys(track.times.size());
    (*curve)->evaluate(track.times.data(), track.times.size(), at_keys.data());
    const KeyJumps alone = key_jumps(**curve, track.times), given = key_jumps(**curve, track.times, at_keys.data());
    EXPECT_EQ(alone.velocity, given.velocity) << m.name;
    EXPECT_EQ(alone.acceleration, given.acceleration) << m.name;
    EXPECT_GT(alone.velocity + alone.acceleration, 0.0) << m.name;
  }
}

}  // namespace
}  // namespace rotinterp
