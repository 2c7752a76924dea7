// The BVH writer's fast 6-decimal text equals std::to_chars(fixed, 6) byte for
// byte: on random values of every magnitude the writer meets, on exact and near
// ties (…5 in the 7th decimal), on zero and on values its fast path hands over.
#include "rotinterp/io/files/fixed6.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace rotinterp {
namespace {

std::string fast(double v) {
  char buf[kFixed6MaxChars];
  return std::string(buf, write_fixed6(buf, buf + sizeof buf, v));
}

std::string reference(double v) {
  char buf[400];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 6).ptr);
}

TEST(Fixed6, EqualsToCharsOnAMillionRandomValuesOfEveryMagnitude) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> exponent(-9.0, 9.0);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> sign(0, 1);
  for (int i = 0; i < 1000000; ++i) {
    const double v = (sign(rng) ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, exponent(rng));
    ASSERT_EQ(fast(v), reference(v)) << std::hexfloat << v;
  }
}

TEST(Fixed6, EqualsToCharsOnTiesAndNearTies) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> whole(-400000000, 400000000);
  for (int i = 0; i < 200000; ++i) {
    // k·10⁻⁶ + 5·10⁻⁷ as decimal text read back (the double nearest a written tie),
    // and its neighbours a few ulps away on both sides.
    const long long k = whole(rng);
    const double tie = std::stod(std::to_string(k) + "5e-7");
    double v = tie;
    for (int s = 0; s < 4; ++s) v = std::nextafter(v, -INFINITY);
    for (int s = 0; s < 9; ++s, v = std::nextafter(v, INFINITY)) ASSERT_EQ(fast(v), reference(v)) << std::hexfloat << v;
  }
}

TEST(Fixed6, EqualsToCharsOnSpecialValues) {
  for (double v : {0.0, -0.0, 1e-6, -1e-6, 4.9999999e-7, 5e-7, -5e-7, 5.0000001e-7, 0.5, -0.5, 179.999999, -180.0,
                   999999.9999995, 1e6, -1e6, 1e12, 123456789.1234565, std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::denorm_min(), 3.0000005, 2.0000015})
    EXPECT_EQ(fast(v), reference(v)) << std::hexfloat << v;
}

}  // namespace
}  // namespace rotinterp
