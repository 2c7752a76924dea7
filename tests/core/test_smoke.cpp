#include "rotinterp/core/rotation.h"
#include <gtest/gtest.h>
TEST(Smoke, ExpOfZeroIsIdentity) { EXPECT_EQ(rotinterp::exp(rotinterp::RotVec()).w(), 1.0); }
