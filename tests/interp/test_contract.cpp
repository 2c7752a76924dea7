// The contract every registered interpolator keeps, run over methods(): passes
// through the keys, unit and finite output on hard fixtures, sign independence,
// clamping, batch = pointwise, the continuity and invariance it claims, and the
// closed-form angular velocity.
#include "contract.h"

namespace rotinterp {
namespace {

using namespace test;

TEST(CoreFix, AngularDistanceIsTheRotationAngleNotHalfOfIt) {
  // The foundation's 2·atan2(|a − b|, |a + b|) returned θ/2; fixed to 4·atan2.
  for (double angle : {1e-9, 0.3, 1.5707963267948966, 3.0, kPi})
    EXPECT_NEAR(angular_distance(Quat::Identity(), rot(Vec3(1, -2, 0.5), angle)), angle, 1e-15 + 1e-15 * angle);
  EXPECT_NEAR(angular_distance(Rz(0.2), Quat(-Rz(-0.3).coeffs())), 0.5, 1e-15);
}

TEST(Registry, ListsTheMethodsInTheirStableOrder) {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods()) names.push_back(m.name);
  const std::vector<std::string> expected = {"slerp", "squad", "expmap", "nlerp", "bf", "c2", "expmap-c2", "clamped", "gltf-cubic"};
  EXPECT_EQ(names, expected);
  EXPECT_EQ(method_names(), "slerp, squad, expmap, nlerp, bf, c2, expmap-c2, clamped, gltf-cubic");
  EXPECT_EQ(find_method("nope"), nullptr);
  auto r = make_interpolator("nope", make({0}, {Quat::Identity()}));
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("valid: slerp"), std::string::npos);
}

TEST(Registry, RejectsInvalidTracksWithOneLineErrors) {
  for (const MethodInfo& m : methods()) {
    auto bad_times = m.make(make({0, 0}, {Quat::Identity(), Quat::Identity()}));
    ASSERT_FALSE(bad_times) << m.name;
    EXPECT_NE(bad_times.error().find("increasing"), std::string::npos) << bad_times.error();
    auto empty = m.make(RotationTrack{});
    EXPECT_FALSE(empty) << m.name;
    auto nan = m.make(make({0, 1}, {Quat::Identity(), Quat(std::nan(""), 0, 0, 0)}));
    EXPECT_FALSE(nan) << m.name;
    auto nonunit = m.make(make({0, 1}, {Quat::Identity(), Quat(2, 0, 0, 0)}));
    EXPECT_FALSE(nonunit) << m.name;
  }
}

TEST_P(Contract, PassesThroughEveryKeyOnEveryFixture) {
  for (const Fixture& f : hard_fixtures()) {
    auto p = build(method(), f.track);
    ASSERT_TRUE(p) << f.name;
    for (std::size_t k = 0; k < f.track.keys.size(); ++k)
      EXPECT_LT(angular_distance(p->evaluate(f.track.times[k]), f.track.keys[k]), kKeyTolerance)
          << f.name << " key " << k;
  }
}

TEST_P(Contract, OutputIsUnitAndFiniteOnEveryFixture) {
  for (const Fixture& f : hard_fixtures()) {
    auto p = build(method(), f.track);
    ASSERT_TRUE(p) << f.name;
    std::vector<double> t = dense_times(f.track, 97);
    t.push_back(std::numeric_limits<double>::quiet_NaN());
    t.push_back(std::numeric_limits<double>::infinity());
    t.push_back(-std::numeric_limits<double>::infinity());
    for (double x : t) {
      const Quat q = p->evaluate(x);
      ASSERT_TRUE(q.coeffs().allFinite()) << f.name << " t=" << x;
      EXPECT_NEAR(q.norm(), 1.0, kUnitTolerance) << f.name << " t=" << x;
      ASSERT_TRUE(p->angular_velocity(x).allFinite()) << f.name << " t=" << x;
    }
  }
}

TEST_P(Contract, BatchEvaluationEqualsPointwiseSortedOrNot) {
  const RotationTrack track = random_track(21, 9, 1.2, 0.05, 0.6);
  auto p = build(method(), track);
  ASSERT_TRUE(p);
  std::vector<double> t = dense_times(track, 13);
  std::mt19937_64 rng(3);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Quat> out(t.size());
    p->evaluate(t.data(), t.size(), out.data());
    for (std::size_t s = 0; s < t.size(); ++s)
      EXPECT_LT(angular_distance(out[s], p->evaluate(t[s])), 1e-15) << "pass " << pass << " t=" << t[s];
    std::shuffle(t.begin(), t.end(), rng);
  }
}

TEST_P(Contract, ClampsOutsideTheKeyRange) {
  const RotationTrack track = random_track(23, 5, 1.0, 0.2, 0.4);
  auto p = build(method(), track);
  ASSERT_TRUE(p);
  EXPECT_LT(angular_distance(p->evaluate(track.times.front() - 5.0), track.keys.front()), kKeyTolerance);
  EXPECT_LT(angular_distance(p->evaluate(track.times.back() + 5.0), track.keys.back()), kKeyTolerance);
  EXPECT_EQ(p->angular_velocity(track.times.back() + 5.0), Vec3::Zero());
}

TEST_P(Contract, CurveDoesNotDependOnTheStoredSignOfKeys) {
  RotationTrack track = random_track(29, 10, 1.5, 0.1, 0.3);
  auto p = build(method(), track);
  RotationTrack flipped = track;
  for (std::size_t k = 1; k < flipped.keys.size(); k += 2) flipped.keys[k].coeffs() *= -1.0;
  flipped.keys[4].coeffs() *= -1.0;
  auto f = build(method(), flipped);
  ASSERT_TRUE(p && f);
  for (double x : dense_times(track, 17)) EXPECT_LT(angular_distance(p->evaluate(x), f->evaluate(x)), 1e-12) << x;
}

TEST_P(Contract, AcceptsAKeyStoredAsMinusThePreviousOne) {
  // fuzz_interp input 120d981b (tests/fuzz/corpus/interp): the identity at t ≈ 6e-304,
  // then −identity — the same orientation — at t = 1. Not sign-continuous as stored,
  // which every method must accept (it aligns the keys itself) and hold still on.
  auto p = build(method(), make({5.696189077778435e-304, 1.0}, {Quat::Identity(), Quat(-1, 0, 0, 0)}));
  ASSERT_TRUE(p);
  for (int i = -2; i <= 34; ++i) {
    const Quat q = p->evaluate(i / 32.0);
    ASSERT_TRUE(q.coeffs().allFinite()) << i;
    EXPECT_LT(angular_distance(q, Quat::Identity()), 1e-15) << i;
  }
}

TEST_P(Contract, Follows22DegreePathWhereKeysLook338DegreesApartAsStored) {
  // Rz(0), −Rz(22.1°), Rz(44.2°): dot(q₀, q₁) = −0.981 as stored.
  const double step = 22.1 * kPi / 180.0;
  RotationTrack t = make({0, 1, 2}, {Rz(0.0), Quat(-Rz(step).coeffs()), Rz(2 * step)});
  ASSERT_NEAR(t.keys[0].dot(t.keys[1]), -0.981, 5e-4);
  auto p = build(method(), t);
  ASSERT_TRUE(p);
  for (int s = 0; s <= 200; ++s) {
    const double x = 2.0 * s / 200.0;
    const Quat q = p->evaluate(x);
    // On the z axis, and never further than the keys it lies between.
    EXPECT_LT(std::hypot(q.x(), q.y()), 1e-12) << x;
    const double angle = 2.0 * std::atan2(q.z(), q.w());
    EXPECT_GE(angle, -1e-9) << x;
    EXPECT_LE(angle, 2 * step + 1e-9) << x;
    EXPECT_LE(std::abs(angle - step * x), 0.25 * step) << x;
  }
}

TEST_P(Contract, KeysExactlyHalfATurnApartFollowTheDocumentedPath) {
  // slerp.h: +180°·t about the axis of log(q₀⁻¹q₁) (first non-zero component
  // positive) — whatever the stored sign of the second key. Every method follows
  // that half-turn (nlerp and gltf-cubic, normalized blends, at their own speed);
  // the invariant ones from any start.
  const bool invariant = method().coordinate_invariant;
  const std::vector<Quat> starts = {Quat::Identity(), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  for (const Quat& a : starts) {
    if (!invariant && !a.isApprox(Quat::Identity())) continue;
    for (double sign : {1.0, -1.0}) {
      const Quat half(0, 0, sign, 0);  // ±180° about y: the same orientation
      RotationTrack t = make({0, 2}, {a, a * half});
      ASSERT_EQ(t.keys[0].dot(t.keys[1]), 0.0);
      auto p = build(method(), t);
      ASSERT_TRUE(p);
      double previous = 0.0;
      for (int s = 1; s < 64; ++s) {
        Quat local = a.conjugate() * p->evaluate(2.0 * s / 64);
        if (local.w() < 0.0) local.coeffs() *= -1.0;
        EXPECT_LT(std::hypot(local.x(), local.z()), 1e-9) << s << " " << sign;  // about y …
        const double angle = 2.0 * std::atan2(local.y(), local.w());          // … positively
        EXPECT_GT(angle, previous) << s << " " << sign;
        if (GetParam() != "nlerp" && GetParam() != "gltf-cubic") {
          EXPECT_NEAR(angle, kPi * s / 64, curve_tolerance(GetParam(), 1e-9)) << s << " " << sign;
        }
        previous = angle;
      }
    }
  }
}

TEST_P(Contract, ExactOnConstantAngularVelocityAtUniformAndNonUniformKeys) {
  if (!method().exact_on_constant_velocity) GTEST_SKIP() << "not claimed by " << GetParam();
  const Vec3 omega(0.9, -1.7, 2.3);  // |ω| = 3 rad/s: key steps up to 2.6 rad (< π)
  const Quat q0 = Quat(Eigen::AngleAxisd(2.0, Vec3(-1, 4, 2).normalized()));
  const std::vector<std::vector<double>> timings = {
      {0.0, 0.3, 0.6, 0.9, 1.2, 1.5},          // uniform
      {0.0, 0.4, 0.45, 1.3, 1.35, 1.9, 2.05},  // non-uniform
      {0, 1.0 / 3.0, 2.0 / 3.0, 0.7, 0.7 + 1e-3, 1.5},
  };
  std::mt19937_64 rng(5);
  for (const auto& times : timings) {
    auto p = build(method(), test::constant_velocity_track(omega, q0, times));
    ASSERT_TRUE(p);
    std::uniform_real_distribution<double> at(times.front(), times.back());
    double worst = 0.0;
    for (int s = 0; s < 400; ++s) {
      const double x = at(rng);
      worst = std::max(worst, angular_distance(p->evaluate(x), integrate_angular_velocity(q0, omega, x)));
      EXPECT_LT((p->angular_velocity(x) - omega).norm(), 1e-8) << x;
    }
    EXPECT_LT(worst, curve_tolerance(GetParam(), 1e-12)) << "keys at " << times.size() << " times starting " << times[1];
  }
}

TEST_P(Contract, AngularVelocityMatchesFiniteDifferencesOfTheCurve) {
  const RotationTrack track = random_track(31, 8, 1.2, 0.1, 0.5);
  auto p = build(method(), track);
  ASSERT_TRUE(p && p->has_angular_velocity());
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for (std::size_t k = 0; k + 1 < track.times.size(); ++k) {
    const double x = track.times[k] + u(rng) * (track.times[k + 1] - track.times[k]);
    const Vec3 fd = test::central_velocity(*p, x, 1e-5);
    const Vec3 w = p->angular_velocity(x);
    EXPECT_LT((w - fd).norm(), 1e-6 * (1.0 + w.norm())) << "segment " << k << " ω " << w.transpose();
  }
}

TEST_P(Contract, AngularAccelerationMatchesFiniteDifferencesOfTheCurve) {
  // Inside segments and at keys, where it is the segment starting there: the second
  // difference of the curve itself on that side (one_sided_acceleration, O(h³), step
  // 1e-3 of the segment), so neither the closed forms nor the velocity's quotient
  // are taken on trust.
  const RotationTrack track = random_track(37, 8, 1.2, 0.1, 0.5);
  auto p = build(method(), track);
  ASSERT_TRUE(p && p->has_angular_acceleration());
  for (std::size_t k = 0; k + 1 < track.times.size(); ++k)
    for (double u : {0.0, 0.23, 0.5, 0.91}) {
      const double d = track.times[k + 1] - track.times[k];
      const double x = track.times[k] + u * d;
      const Vec3 fd = test::one_sided_acceleration(*p, x, 1e-3 * d);
      const Vec3 a = p->angular_acceleration(x);
      EXPECT_LT((a - fd).norm(), 1e-5 * (1.0 + a.norm())) << "segment " << k << " u " << u << " α " << a.transpose();
    }
  EXPECT_EQ(p->angular_acceleration(track.times.back() + 1.0), Vec3::Zero());
}

// Velocity and acceleration jumps across interior keys, relative to the curve's
// velocity / acceleration scale, measured by one-sided finite differences.
struct Jumps {
  double velocity = 0.0;
  double acceleration = 0.0;
};
Jumps measure_jumps(const Interpolator& p, const RotationTrack& track) {
  Jumps j;
  double vscale = 0.0, ascale = 0.0;
  for (std::size_t k = 1; k + 1 < track.times.size(); ++k) {
    const double t = track.times[k];
    const double h = 2e-3 * std::min(t - track.times[k - 1], track.times[k + 1] - t);
    const Vec3 vl = test::one_sided_velocity(p, t, -h), vr = test::one_sided_velocity(p, t, h);
    const Vec3 al = test::one_sided_acceleration(p, t, -h), ar = test::one_sided_acceleration(p, t, h);
    vscale = std::max({vscale, vl.norm(), vr.norm()});
    ascale = std::max({ascale, al.norm(), ar.norm()});
    j.velocity = std::max(j.velocity, (vl - vr).norm());
    j.acceleration = std::max(j.acceleration, (al - ar).norm());
  }
  j.velocity /= vscale;
  j.acceleration /= ascale;
  return j;
}

TEST_P(Contract, ContinuityAtKeysIsExactlyAsClaimed) {
  // Relative jumps: the finite differences leave ~1e-6 (velocity, O(h²)) and
  // ~1e-5 (acceleration, O(h³)/h-noise) on smooth curves; a real jump is O(1).
  constexpr double kSmooth = 1e-4, kJump = 1e-2;
  for (std::uint64_t seed : {41u, 43u}) {
    const RotationTrack track = random_track(seed, 9, 1.0, 0.1, 0.6);
    auto p = build(method(), track);
    ASSERT_TRUE(p);
    const Jumps j = measure_jumps(*p, track);
    RecordProperty("velocity_jump_" + std::to_string(seed), std::to_string(j.velocity));
    RecordProperty("acceleration_jump_" + std::to_string(seed), std::to_string(j.acceleration));
    const int c = method().continuity;
    if (c >= 1) {
      EXPECT_LT(j.velocity, kSmooth) << "claims C1";
    } else {
      EXPECT_GT(j.velocity, kJump) << "claims only C0";
    }
    if (c >= 2) {
      EXPECT_LT(j.acceleration, kSmooth) << "claims C2";
    } else if (c == 1) {
      EXPECT_GT(j.acceleration, kJump) << "claims only C1";
    }
  }
}

TEST_P(Contract, CoordinateInvarianceIsExactlyAsClaimed) {
  const RotationTrack track = random_track(47, 8, 1.0, 0.1, 0.4);
  std::mt19937_64 rng(13);
  const Quat R = random_quat(rng), S = random_quat(rng);
  RotationTrack moved = track;
  for (Quat& q : moved.keys) q = R * q * S;
  auto p = build(method(), track);
  auto m = build(method(), moved);
  ASSERT_TRUE(p && m);
  double worst = 0.0;
  for (double x : dense_times(track, 23)) worst = std::max(worst, angular_distance(R * p->evaluate(x) * S, m->evaluate(x)));
  RecordProperty("invariance_deviation_rad", std::to_string(worst));
  if (method().coordinate_invariant) {
    EXPECT_LT(worst, kInvarianceTolerance);
  } else {
    // Not invariant, and by how much: recorded above (and printed here).
    EXPECT_GT(worst, kInvarianceTolerance);
    std::printf("[ info ] %s: coordinate-invariance deviation %.3g rad\n", GetParam().c_str(), worst);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, Contract, ::testing::ValuesIn(test::all_method_names()),
                         test::method_test_name);

}  // namespace
}  // namespace rotinterp
