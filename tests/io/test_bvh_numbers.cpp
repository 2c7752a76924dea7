// parse_bvh reads every value exactly as std::from_chars does (its fast path for
// plain decimals must give the same double, bit for bit), in every text form a
// writer may use: fixed with 0–15 digits, negative zero, exponents, leading '+'.
#include "rotinterp/io/bvh/bvh.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

TEST(BvhNumbers, EveryValueEqualsFromCharsBitForBit) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> mag(-7.0, 5.0);
  std::uniform_int_distribution<int> prec(0, 17), form(0, 9);
  constexpr int kColumns = 6, kFrames = 40000;
  std::vector<std::string> tokens;
  tokens.reserve(kColumns * kFrames);
  for (int i = 0; i < kColumns * kFrames; ++i) {
    const double v = (rng() % 2 ? -1.0 : 1.0) * std::pow(10.0, mag(rng));
    char buf[64];
    const int f = form(rng);
    if (f < 7) std::snprintf(buf, sizeof buf, "%.*f", prec(rng), v);     // fixed, up to 17 decimals
    else if (f == 7) std::snprintf(buf, sizeof buf, "%.*e", prec(rng), v);
    else if (f == 8) std::snprintf(buf, sizeof buf, "%s", i % 2 ? "-0.000000" : "-0");
    else std::snprintf(buf, sizeof buf, "+%.6f", std::abs(v));
    tokens.emplace_back(buf);
  }
  std::string text =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      " End Site\n {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: " + std::to_string(kFrames) + "\nFrame Time: 0.008333\n";
  for (int r = 0; r < kFrames; ++r) {
    for (int c = 0; c < kColumns; ++c) text += (c ? " " : "") + tokens[static_cast<std::size_t>(r * kColumns + c)];
    text += "\n";
  }
  Result<BvhFile> file = parse_bvh(text, "numbers.bvh");
  ASSERT_TRUE(file) << file.error();
  ASSERT_EQ(file->values.size(), tokens.size());
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    std::string_view t = tokens[i];
    if (t.front() == '+') t.remove_prefix(1);
    double expected = 0.0;
    ASSERT_EQ(std::from_chars(t.data(), t.data() + t.size(), expected).ec, std::errc());
    ASSERT_EQ(std::memcmp(&expected, &file->values[i], sizeof(double)), 0) << tokens[i];
  }
}

}  // namespace
}  // namespace rotinterp
