// MethodInfo::support, checked: a key added, removed or changed leaves every sample outside
// the support-th keys on either side of it bit for bit as it was (up to the sign of the quaternion).
#include "support.h"

#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

// Times `support` keys before and after time c in the key times `t` (strictly), or
// the track's ends.
std::pair<double, double> moved_span(const std::vector<double>& t, double c, int support) {
  const auto s = static_cast<std::ptrdiff_t>(support);
  const auto below = std::lower_bound(t.begin(), t.end(), c) - t.begin();  // keys before c
  const auto above = std::upper_bound(t.begin(), t.end(), c) - t.begin();  // first key after c
  const double lo = below - s >= 0 ? t[static_cast<std::size_t>(below - s)] : t.front();
  const double hi = above + s - 1 < static_cast<std::ptrdiff_t>(t.size()) ? t[static_cast<std::size_t>(above + s - 1)] : t.back();
  return {lo, hi};
}

bool same_up_to_sign(const Quat& a, const Quat& b) { return a.coeffs() == b.coeffs() || a.coeffs() == -b.coeffs(); }

// Samples on a frame grid (as reduce evaluates) of the curves through `a` and `b`,
// which differ at the key time c: equal outside c's span in both.
void expect_unmoved_outside_support(const MethodInfo& m, const RotationTrack& a, const RotationTrack& b, double c,
                                    const std::string& what) {
  auto ca = m.make(a), cb = m.make(b);
  ASSERT_TRUE(ca && cb) << what;
  const auto [alo, ahi] = moved_span(a.times, c, m.support);
  const auto [blo, bhi] = moved_span(b.times, c, m.support);
  const double lo = std::min(alo, blo), hi = std::max(ahi, bhi);
  int checked = 0;
  for (double t = a.times.front(); t <= a.times.back(); t += 1.0 / 120) {
    if (t >= lo && t <= hi) continue;
    ++checked;
    ASSERT_TRUE(same_up_to_sign((*ca)->evaluate(t), (*cb)->evaluate(t)))
        << m.name << ", " << what << " at " << c << ": the curve moved at t = " << t << ", outside [" << lo << ", " << hi
        << "]";
  }
  EXPECT_GT(checked, 0) << what;
}

TEST(MethodSupport, AKeyAddedRemovedOrChangedMovesTheCurveOnlyWithinTheMethodsSupport) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const MethodInfo& m : methods()) {
    if (m.support == 0) continue;  // global: no claim
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
      std::mt19937_64 rng(seed);
      // Steps up to 3 rad (neighbours that flip hemisphere), 2 to 12 frames apart.
      RotationTrack track = test::random_track(seed, 16, 3.0, 2.0 / 120, 12.0 / 120);
      for (double& t : track.times) t = std::round(t * 120) / 120;
      const auto k = 1 + static_cast<std::size_t>(u(rng) * 14);  // an interior key
      // Added: a key in the middle of the interval after k.
      RotationTrack added = track;
      const double c = std::round(60 * (track.times[k] + track.times[k + 1])) / 120;
      if (c > track.times[k] && c < track.times[k + 1]) {
        added.times.insert(added.times.begin() + static_cast<std::ptrdiff_t>(k + 1), c);
        added.keys.insert(added.keys.begin() + static_cast<std::ptrdiff_t>(k + 1), test::random_quat(rng));
        expect_unmoved_outside_support(m, track, added, c, "added");
      }
      // Removed: key k.
      RotationTrack removed = track;
      removed.times.erase(removed.times.begin() + static_cast<std::ptrdiff_t>(k));
      removed.keys.erase(removed.keys.begin() + static_cast<std::ptrdiff_t>(k));
      expect_unmoved_outside_support(m, track, removed, track.times[k], "removed");
      // Changed: key k's value turned a little (as a refit does), or negated.
      RotationTrack changed = track;
      changed.keys[k] = apply_moving(track.keys[k], RotVec(test::random_unit(rng) * 1e-6));
      expect_unmoved_outside_support(m, track, changed, track.times[k], "changed");
      changed.keys[k] = Quat(-track.keys[k].coeffs());
      expect_unmoved_outside_support(m, track, changed, track.times[k], "negated");
    }
  }
}

// A support claimed one key too narrow is caught: each local method's curve moves
// beyond support − 1 keys of a change on some track.
TEST(MethodSupport, EachLocalMethodsSupportIsNoWiderThanItNeedsToBeCaught) {
  for (const MethodInfo& m : methods()) {
    if (m.support == 0) continue;
    MethodInfo narrower = m;
    narrower.support = m.support - 1;
    bool moved = false;
    for (std::uint64_t seed = 1; seed <= 10 && !moved; ++seed) {
      RotationTrack track = test::random_track(seed, 10, 1.0, 2.0 / 120, 12.0 / 120);
      RotationTrack changed = track;
      changed.keys[5] = apply_moving(track.keys[5], RotVec(Vec3(0.0, 0.0, 0.3)));
      auto ca = m.make(track), cb = m.make(changed);
      ASSERT_TRUE(ca && cb);
      const auto [lo, hi] = moved_span(track.times, track.times[5], narrower.support);
      for (double t = track.times.front(); t <= track.times.back() && !moved; t += 1.0 / 240)
        if ((t < lo || t > hi) && !same_up_to_sign((*ca)->evaluate(t), (*cb)->evaluate(t))) moved = true;
    }
    EXPECT_TRUE(moved) << m.name << ": support " << m.support << " is wider than the curve's";
  }
}

}  // namespace
}  // namespace rotinterp
