// The keys-per-call limit (clip/key_limit.h): frames × joints against kMaxKeys, with
// no overflow and NaN refused, and its one-line text.
#include "rotinterp/clip/key_limit.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp {
namespace {

TEST(KeyLimit, FramesTimesJointsPassTheLimitExactlyAboveIt) {
  EXPECT_FALSE(too_many_keys(static_cast<double>(kMaxKeys), 1));
  EXPECT_TRUE(too_many_keys(static_cast<double>(kMaxKeys) + 1, 1));
  EXPECT_FALSE(too_many_keys(static_cast<double>(kMaxKeys / 4), 4));
  EXPECT_TRUE(too_many_keys(static_cast<double>(kMaxKeys / 4) + 1, 4));
  EXPECT_TRUE(too_many_keys(1e300, 1000000));  // a duration over a tiny frame time
  EXPECT_TRUE(too_many_keys(std::nan(""), 1));
  EXPECT_FALSE(too_many_keys(1e300, 0));  // no joints, no keys
}

TEST(KeyLimit, TheRefusalNamesFramesJointsAndTheLimit) {
  EXPECT_EQ(too_many_keys_text(1500000001.0, 2), "1500000001 frames × 2 joints, more than 100000000 keys");
  EXPECT_EQ(too_many_keys_text(4e8, 1), "400000000 frames × 1 joint, more than 100000000 keys");
}

}  // namespace
}  // namespace rotinterp
