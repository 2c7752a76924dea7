// The selection's insertion for local methods (select_local.cpp): the same keys and errors as
// measuring every frame, found by measuring only the frames each new key moves.
#include "reducer.h"

#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp::detail {
namespace {

constexpr double kTolerance = 0.01;  // rad

// A noisy random walk of `frames` orientations at 120 Hz: turns that change direction
// every few frames, some held stretches, neighbours up to 170° apart now and then.
struct Signal {
  std::vector<double> times;
  std::vector<Quat> q;
};
Signal random_signal(std::uint64_t seed, std::size_t frames) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Signal s;
  Quat q = Quat::Identity();
  Vec3 w(g(rng), g(rng), g(rng));
  for (std::size_t f = 0; f < frames; ++f) {
    s.times.push_back(static_cast<double>(f) / 120);
    s.q.push_back(q);
    if (u(rng) < 0.1) w = Vec3(g(rng), g(rng), g(rng)) * (u(rng) < 0.2 ? 0.0 : 3.0);
    const double jump = u(rng) < 0.01 ? 2.9 : 0.0;
    q = apply_moving(q, RotVec(w / 120 + Vec3(g(rng), g(rng), g(rng)) * 0.002 + Vec3(jump, 0, 0)));
  }
  return s;
}

// The error of the curve of `method` through the signal's frames `keys`, at [lo, hi];
// every call's measured span and whether it was every frame.
struct Measuring {
  Measuring(std::string m, const Signal* s) : method(std::move(m)), signal(s) {}
  std::string method;
  const Signal* signal;
  std::size_t whole = 0, frames = 0;
  ErrorFn fn() {
    return [this](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
      RotationTrack t;
      for (std::size_t k : keys) t.times.push_back(signal->times[k]), t.keys.push_back(signal->q[k]);
      auto c = make_interpolator(method, t);
      if (!c) return c.failure();
      std::vector<Quat> q(hi - lo + 1);
      (*c)->evaluate(signal->times.data() + lo, q.size(), q.data());
      for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = angular_distance(signal->q[f], q[f - lo]) / kTolerance;
      if (lo == 0 && hi + 1 == signal->q.size()) ++whole;
      frames += hi - lo + 1;
      return Ok{};
    };
  }
};

TEST(SelectLocal, KeysAndErrorsEqualMeasuringEveryFrameOnRandomTracks) {
  for (const MethodInfo& m : methods()) {
    if (m.support == 0) continue;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const Signal s = random_signal(seed, 400 + 37 * seed);
      const std::size_t n = s.q.size();
      Measuring every{m.name, &s}, local{m.name, &s};
      std::vector<std::size_t> k_every = ends(n), k_local = ends(n);
      std::vector<double> e_every, e_local;
      ASSERT_TRUE(select_keys(k_every, n, every.fn(), nullptr, true, e_every, false, 0));
      ASSERT_TRUE(select_keys(k_local, n, local.fn(), nullptr, true, e_local, false, static_cast<std::size_t>(m.support)));
      EXPECT_EQ(k_local, k_every) << m.name << " seed " << seed;
      // The errors left are the whole curve's at every frame, bit for bit.
      std::vector<double> whole(n);
      ASSERT_TRUE(every.fn()(k_local, 0, n - 1, whole.data()));
      ASSERT_EQ(e_local.size(), n);
      for (std::size_t f = 0; f < n; ++f) ASSERT_EQ(e_local[f], whole[f]) << m.name << " seed " << seed << " frame " << f;
      EXPECT_LT(local.frames, every.frames) << m.name << " seed " << seed;
    }
  }
}

// Inserting only (as a later pass of a hierarchical run does), errors known on entry,
// from keys every 8th frame: no measure of every frame, and per new key only the
// frames within the method's support of it — 2·support key intervals, each at most 8
// frames — measured again.
TEST(SelectLocal, EachNewKeyIsMeasuredOnlyWithinTheMethodsSupport) {
  constexpr std::size_t kEvery = 8;
  for (const MethodInfo& m : methods()) {
    if (m.support == 0) continue;
    const Signal s = random_signal(99, 901);
    const std::size_t n = s.q.size();
    std::vector<std::size_t> keys;
    for (std::size_t f = 0; f < n; f += kEvery) keys.push_back(f);
    Measuring probe{m.name, &s};
    std::vector<double> e(n);
    ASSERT_TRUE(probe.fn()(keys, 0, n - 1, e.data()));
    const std::size_t before = keys.size();
    Measuring local{m.name, &s};
    ASSERT_TRUE(select_keys(keys, n, local.fn(), nullptr, false, e, true, static_cast<std::size_t>(m.support)));
    const std::size_t added = keys.size() - before;
    EXPECT_GT(added, 20u) << m.name;
    EXPECT_EQ(local.whole, 0u) << m.name;
    EXPECT_LE(local.frames, added * (2 * static_cast<std::size_t>(m.support) * kEvery + 1)) << m.name;
  }
}

}  // namespace
}  // namespace rotinterp::detail
