// Numeric stress: every registered method over ≥ 10⁶ adversarial key pairs (and
// the quads they form): random, antipodal, exactly 180°, π − 1e-9, 1e-12 and 1e-6
// rad apart, identical; time steps from 1e-6 s to 1e4 s mixed in one track. Every
// output must be a finite unit quaternion and every key must be hit (< 1e-9 rad).
// Under the sanitizers the count is 10⁵ (the same cases, ten times fewer).
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <future>
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
constexpr std::size_t kKeysPerTrack = 64;  // short tracks: many starts and ends

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

struct Worst {
  std::size_t pairs = 0, samples = 0;
  double key = 0.0, norm = 0.0;
  bool finite = true;
  std::string error;
};

// Runs `pairs` adversarial key pairs through one method, tracks seeded by `seed`.
Worst stress(const MethodInfo& m, std::size_t pairs, std::uint64_t seed) {
  Worst w;
  std::mt19937_64 rng(seed);
  while (w.pairs < pairs) {
    const RotationTrack track = adversarial_track(rng);
    auto interp = make_interpolator(m.name, track);
    if (!interp.ok()) {
      w.error = interp.error();
      return w;
    }
    const Interpolator& f = **interp;
    for (std::size_t k = 0; k < track.times.size(); ++k) {
      const Quat at_key = f.evaluate(track.times[k]);
      w.finite = w.finite && at_key.coeffs().allFinite();
      w.key = std::max(w.key, angular_distance(at_key, track.keys[k]));
      if (k + 1 == track.times.size()) continue;
      for (double h : {0.25, 0.5, 0.75}) {
        const Quat q = f.evaluate(track.times[k] + h * (track.times[k + 1] - track.times[k]));
        w.finite = w.finite && q.coeffs().allFinite();
        w.norm = std::max(w.norm, std::abs(q.norm() - 1.0));
        ++w.samples;
      }
    }
    w.pairs += track.times.size() - 1;
  }
  return w;
}

}  // namespace

std::vector<std::string> method_list() {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods()) names.push_back(m.name);
  return names;
}

class NumericStress : public ::testing::TestWithParam<std::string> {};

TEST_P(NumericStress, FiniteUnitOutputAndKeysHitOnAMillionAdversarialPairs) {
  const MethodInfo* method = find_method(GetParam());
  ASSERT_NE(method, nullptr);
  const MethodInfo& m = *method;
  {
    const auto start = std::chrono::steady_clock::now();
    // Two halves in parallel (the machine has two cores), different seeds.
    auto half = std::async(std::launch::async, stress, std::cref(m), kPairsPerMethod / 2, 1);
    const Worst a = stress(m, kPairsPerMethod - kPairsPerMethod / 2, 2);
    const Worst b = half.get();
    ASSERT_TRUE(a.error.empty() && b.error.empty()) << m.name << ": " << a.error << b.error;
    EXPECT_TRUE(a.finite && b.finite) << m.name;
    const double worst_key = std::max(a.key, b.key), worst_norm = std::max(a.norm, b.norm);
    EXPECT_LT(worst_key, 1e-9) << m.name;
    EXPECT_LT(worst_norm, 1e-12) << m.name;
    EXPECT_GE(a.pairs + b.pairs, kPairsPerMethod);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-9s %zu pairs, %zu samples in %.1f s: worst key error %.3g rad, worst |q|-1 %.3g\n", m.name.c_str(),
                a.pairs + b.pairs, a.samples + b.samples, seconds, worst_key, worst_norm);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, NumericStress, ::testing::ValuesIn(method_list()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });
