// Numeric stress: every registered method over ≥ 10⁶ adversarial key pairs (and
// the quads they form): random, antipodal, exactly 180°, π − 1e-9, 1e-12 and 1e-6
// rad apart, identical; time steps from 1e-6 s to 1e4 s mixed in one track. Every
// output must be a finite unit quaternion and every key must be hit (< 1e-9 rad).
// Under the sanitizers the count is 10⁵ (the same cases, ten times fewer).
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace rotinterp;

namespace {

#ifdef ROTINTERP_SANITIZED
constexpr std::size_t kPairsPerMethod = 100'000;
#else
constexpr std::size_t kPairsPerMethod = 1'000'000;
#endif
constexpr std::size_t kKeysPerTrack = 10'000;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v(n(rng), n(rng), n(rng));
  return v.norm() > 1e-9 ? Vec3(v.normalized()) : Vec3::UnitX();
}

// One track whose consecutive keys cycle through the adversarial relations.
RotationTrack adversarial_track(std::mt19937_64& rng) {
  static const double kSteps[] = {1e-6, 1e-3, 1.0 / 30.0, 1.0, 1e4};
  std::uniform_int_distribution<int> pick_step(0, 4), pick_kind(0, 7);
  std::uniform_real_distribution<double> jitter(0.5, 1.5), angle(0.0, kPi);
  RotationTrack track;
  Quat q = exp(RotVec(random_unit(rng) * angle(rng)));
  double t = 0.0;
  for (std::size_t k = 0; k < kKeysPerTrack; ++k) {
    track.times.push_back(t);
    track.keys.push_back(q);
    t += kSteps[pick_step(rng)] * jitter(rng);
    const Vec3 axis = random_unit(rng);
    switch (pick_kind(rng)) {
      case 0: q = exp(RotVec(axis * angle(rng))) * q; break;                  // random step below 180°
      case 1: q = Quat(-q.w(), -q.x(), -q.y(), -q.z()); break;                // antipodal: same orientation
      case 2: q = q * Quat(0.0, axis.x(), axis.y(), axis.z()); break;          // exactly 180° apart
      case 3: q = apply_moving(q, RotVec(axis * (kPi - 1e-9))); break;        // just under 180°
      case 4: q = apply_moving(q, RotVec(axis * 1e-12)); break;               // 1e-12 rad apart
      case 5: q = apply_moving(q, RotVec(axis * 1e-6)); break;                // 1e-6 rad apart
      case 6: break;                                                          // identical
      default: q = exp(RotVec(axis * angle(rng))); break;                     // unrelated
    }
  }
  track.make_sign_continuous();
  return track;
}

}  // namespace

TEST(NumericStress, EveryMethodGivesFiniteUnitOutputAndHitsKeysOnAMillionAdversarialPairs) {
  ASSERT_FALSE(methods().empty());
  for (const MethodInfo& m : methods()) {
    std::mt19937_64 rng(12345);
    std::size_t pairs = 0, samples = 0;
    double worst_key = 0.0, worst_norm = 0.0;
    while (pairs < kPairsPerMethod) {
      const RotationTrack track = adversarial_track(rng);
      auto interp = make_interpolator(m.name, track);
      ASSERT_TRUE(interp.ok()) << m.name << ": " << interp.error();
      const Interpolator& f = **interp;
      for (std::size_t k = 0; k < track.times.size(); ++k) {
        const Quat at_key = f.evaluate(track.times[k]);
        ASSERT_TRUE(at_key.coeffs().allFinite()) << m.name << " key " << k;
        worst_key = std::max(worst_key, angular_distance(at_key, track.keys[k]));
        if (k + 1 < track.times.size()) {
          for (double h : {0.25, 0.5, 0.75}) {
            const double t = track.times[k] + h * (track.times[k + 1] - track.times[k]);
            const Quat q = f.evaluate(t);
            ASSERT_TRUE(q.coeffs().allFinite()) << m.name << " between keys " << k << " and " << k + 1;
            worst_norm = std::max(worst_norm, std::abs(q.norm() - 1.0));
            ++samples;
          }
        }
      }
      pairs += track.times.size() - 1;
    }
    EXPECT_LT(worst_key, 1e-9) << m.name;
    EXPECT_LT(worst_norm, 1e-12) << m.name;
    RecordProperty(m.name + "_worst_key_error_rad", std::to_string(worst_key));
    std::printf("%-8s %zu pairs, %zu samples: worst key error %.3g rad, worst |q|-1 %.3g\n", m.name.c_str(), pairs,
                samples, worst_key, worst_norm);
  }
}
