#include "rotinterp/clip/time_range.h"

#include <gtest/gtest.h>

#include <string>

using namespace rotinterp;

TEST(TimeRange, ATextThatIsNotOneIsRefusedWithItsForm) {
  for (const char* bad : {"1", "a:b", "1:2:3", "-1:2", "1.5f:3f", "5f:2f", "2:1", "1x:2"}) {
    auto r = parse_time_range(bad);
    ASSERT_FALSE(r) << bad;
    EXPECT_NE(r.error().find(std::string("--range '") + bad + "'"), std::string::npos) << r.error();
  }
}
