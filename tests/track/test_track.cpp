// The key tracks' invariants (track/track.h): what validate() tells a caller, and
// make_sign_continuous() establishing them.
#include "rotinterp/track/track.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace rotinterp {
namespace {

RotationTrack three_keys(const Quat& middle) {
  RotationTrack t;
  t.times = {0.0, 1.0, 2.0};
  t.keys = {Quat::Identity(), middle, Quat::Identity()};
  return t;
}

TEST(RotationTrackValidate, SaysHowFarAKeyIsFromUnitLength) {
  // A float32-rounded key: off by 2e-5, far beyond the 1e-9 the library allows.
  const Status s = three_keys(Quat(1.00002, 0.0, 0.0, 0.0)).validate();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error(), "rotation key 1 is not unit (|q| = 1.00002, off by 2e-05; the tolerance is 1e-09)");
}

TEST(RotationTrackValidate, AcceptsKeysWithinTheUnitTolerance) {
  EXPECT_TRUE(three_keys(Quat(1.0 + 0.5 * kUnitNormTolerance, 0.0, 0.0, 0.0)).validate());
  EXPECT_FALSE(three_keys(Quat(1.0 + 2.0 * kUnitNormTolerance, 0.0, 0.0, 0.0)).validate());
}

TEST(RotationTrackValidate, NamesTheFirstKeyThatBreaksTimesOrSigns) {
  RotationTrack t = three_keys(Quat::Identity());
  t.times[2] = 1.0;
  EXPECT_EQ(t.validate().error(), "key times are not strictly increasing at key 2");
  t = three_keys(Quat(-1.0, 0.0, 0.0, 0.0));  // the same orientation, the other sign
  EXPECT_EQ(t.validate().error(), "rotation key 1 is not sign-continuous with the previous key");
  t = three_keys(Quat::Identity());
  t.times[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(t.validate().error(), "key 1 has a non-finite time");
  t.times.pop_back();
  EXPECT_FALSE(t.validate());  // two times, three keys
}

TEST(RotationTrackSignContinuity, FlipsEachKeyIntoItsPredecessorsHemisphereAndNormalizes) {
  // Alternating signs of a slow turn, one key slightly off unit length (float input).
  RotationTrack t;
  for (int k = 0; k < 8; ++k) {
    const double a = 0.4 * k;
    const Quat q(std::cos(a / 2), 0.0, std::sin(a / 2), 0.0);
    t.times.push_back(k);
    t.keys.push_back(k % 2 ? Quat(-q.coeffs()) : q);
  }
  t.keys[3].coeffs() *= 1.00002;
  ASSERT_FALSE(t.validate());
  const RotationTrack before = t;
  t.make_sign_continuous();
  ASSERT_TRUE(t.validate()) << t.validate().error();
  for (std::size_t k = 0; k < t.keys.size(); ++k) {
    EXPECT_NEAR(std::abs(t.keys[k].dot(before.keys[k].normalized())), 1.0, 1e-15) << k;  // the same orientation
    if (k > 0) {
      EXPECT_GT(t.keys[k].dot(t.keys[k - 1]), 0.0) << k;
    }
  }
  EXPECT_EQ(t.keys[0].coeffs(), before.keys[0].coeffs());  // the first key keeps its sign
}

TEST(TranslationTrackValidate, RefusesNonFiniteKeysAndUnsortedTimes) {
  TranslationTrack t{{0.0, 1.0}, {Vec3::Zero(), Vec3(1, 2, 3)}};
  EXPECT_TRUE(t.validate());
  t.keys[1].y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(t.validate().error(), "translation key 1 is not finite");
  t.keys[1].y() = 2.0;
  t.times = {1.0, 0.0};
  EXPECT_FALSE(t.validate());
}

}  // namespace
}  // namespace rotinterp
