// slerp evaluated in place on a window of keys (slerp_window.h): bit for bit the curve
// make_slerp builds through the same keys, which the selection's decisions rely on.
#include "slerp_window.h"
#include "select.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/slerp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace rotinterp::detail {
namespace {

// Random values of about unit norm (as refitted values are) in either hemisphere, with
// some neighbours 90° apart in 4-D (their dot product exactly 0), some equal, some opposite.
std::vector<Quat> random_values(std::mt19937_64& rng, std::size_t frames) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Quat> v;
  for (std::size_t f = 0; f < frames; ++f) {
    Quat q(g(rng), g(rng), g(rng), g(rng));
    q.coeffs() *= (1.0 + 1e-12 * g(rng)) / q.norm();
    const double kind = u(rng);
    if (f > 0 && kind < 0.1) q = Quat(-v.back().x(), v.back().w(), -v.back().z(), v.back().y());  // dot exactly 0
    else if (f > 0 && kind < 0.2) q = v.back();
    else if (f > 0 && kind < 0.3) q = Quat(-v.back().coeffs());
    else if (f > 0 && kind < 0.6) q = apply_moving(v.back(), RotVec(Vec3(g(rng), g(rng), g(rng)) * 0.05));
    v.push_back(q);
  }
  return v;
}

std::vector<std::size_t> random_keys(std::mt19937_64& rng, std::size_t frames) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double density = u(rng);
  std::vector<std::size_t> keys;
  for (std::size_t f = 0; f < frames; ++f)
    if (f == 0 || f + 1 == frames || u(rng) < density) keys.push_back(f);
  return keys;
}

void expect_same_bits(const Quat& a, const Quat& b) {
  for (int c = 0; c < 4; ++c) ASSERT_EQ(a.coeffs()[c], b.coeffs()[c]);
}

TEST(SlerpWindow, EveryWindowEqualsMakeSlerpsCurveBitForBit) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t frames = 3 + rng() % 60;
    std::vector<double> times;
    for (std::size_t f = 0; f < frames; ++f) times.push_back(0.25 + static_cast<double>(f) / 120);
    const std::vector<Quat> value = random_values(rng, frames);
    const std::vector<std::size_t> all = random_keys(rng, frames);
    // A window of the keys, and frames inside and around it.
    const std::size_t a = rng() % all.size(), b = std::min(all.size() - 1, a + 1 + rng() % 9);
    const std::vector<std::size_t> keys(all.begin() + static_cast<std::ptrdiff_t>(a), all.begin() + static_cast<std::ptrdiff_t>(b + 1));
    if (keys.size() < 2) continue;
    const auto curve = make_slerp(decimated_track(times, value, keys));
    ASSERT_TRUE(curve);
    const std::size_t lo = rng() % frames, hi = lo + rng() % (frames - lo);
    std::vector<Quat> want(hi - lo + 1), got(hi - lo + 1), whole(hi - lo + 1), prepared;
    (*curve)->evaluate(times.data() + lo, want.size(), want.data());
    slerp_window(times, value, keys, lo, hi, got.data());
    prepare_slerp_keys(value, keys, prepared);
    slerp_frames(times, keys.data(), prepared.data(), keys.size(), lo, hi, whole.data());
    for (std::size_t i = 0; i < want.size(); ++i) {
      expect_same_bits(got[i], want[i]);
      expect_same_bits(whole[i], want[i]);
    }
  }
}

TEST(SlerpWindow, KeysPreparedAgainEqualKeysPreparedAfresh) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t frames = 3 + rng() % 60;
    std::vector<Quat> value = random_values(rng, frames);
    const std::vector<std::size_t> old_keys = random_keys(rng, frames);
    std::vector<Quat> old_values, old_prepared, again, fresh;
    for (std::size_t k : old_keys) old_values.push_back(value[k]);
    prepare_slerp_keys(value, old_keys, old_prepared);
    // Keys added and removed, some values changed (a refit, a reset): everywhere, or
    // (every other trial) at one or two frames, as a pass of the selection does.
    std::vector<std::size_t> keys = random_keys(rng, frames);
    const std::vector<Quat> changed = random_values(rng, frames);
    if (trial % 2) {
      keys = old_keys;
      for (int c = 0; c < 2; ++c) {
        const std::size_t f = rng() % frames;
        if (rng() % 2) value[f] = changed[f];
        else if (!has(keys, f)) add_key(keys, f);
      }
    } else {
      for (std::size_t f = 0; f < frames; ++f)
        if (rng() % 4 == 0) value[f] = changed[f];
    }
    prepare_slerp_keys_again(value, keys, old_keys, old_values, old_prepared, again);
    prepare_slerp_keys(value, keys, fresh);
    ASSERT_EQ(again.size(), fresh.size());
    for (std::size_t k = 0; k < fresh.size(); ++k) expect_same_bits(again[k], fresh[k]);
  }
}

}  // namespace
}  // namespace rotinterp::detail
