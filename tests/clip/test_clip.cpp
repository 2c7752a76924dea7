// The clip model's validation (clip/clip.h): what its messages tell a caller.
#include "rotinterp/clip/clip.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rotinterp
