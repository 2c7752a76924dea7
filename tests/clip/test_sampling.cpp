#include "rotinterp/clip/sampling.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rotinterp;

namespace {

Rate rate(const char* text) {
  auto r = parse_rate(text);
  EXPECT_TRUE(r.ok()) << text;
  return r.ok() ? r.value() : Rate{1, 1};
}

}  // namespace

TEST(Sampling, RatesParseExactlyAsDecimalsOrRationals) {
  EXPECT_EQ(rate("30"), (Rate{30, 1}));
  EXPECT_EQ(rate("59.94"), (Rate{2997, 50}));
  EXPECT_EQ(rate("30000/1001"), (Rate{30000, 1001}));
  EXPECT_EQ(rate("24000/1001"), (Rate{24000, 1001}));
  EXPECT_EQ(rate("120.0"), (Rate{120, 1}));
  EXPECT_EQ(rate("0.5"), (Rate{1, 2}));
  EXPECT_EQ(rate("29.97/1"), (Rate{2997, 100}));
  EXPECT_EQ(rate("30000/1001").to_string(), "30000/1001");
  EXPECT_EQ(rate("59.94").to_string(), "59.94");
  EXPECT_EQ(rate("120").to_string(), "120");
  EXPECT_EQ(rate("99999.123456789012").to_string(), "99999.123456789012");  // 1e17 · 1e12 needs 128 bits
  EXPECT_EQ(sample_count(1e300, Rate{30, 1}), static_cast<std::size_t>(1e18));  // refused by callers, no UB
}

TEST(Sampling, BadRatesAreOneLineErrors) {
  for (const char* bad : {"", "0", "-30", "abc", "30fps", "1/0", "0/5", "3..0", ".", "/", "30/", "1e3", "nan", "inf",
                          "0.0000000000001", "99999999999999999999"}) {
    auto r = parse_rate(bad);
    ASSERT_FALSE(r.ok()) << "'" << bad << "' should be rejected";
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
    EXPECT_NE(r.error().find("frame rate"), std::string::npos) << r.error();
  }
}

TEST(Sampling, PrintedFrameTimesAreRecognizedWithinTheirPrecision) {
  EXPECT_EQ(rate_from_frame_time(0.008333).value(), (Rate{120, 1}));
  EXPECT_EQ(rate_from_frame_time(0.0083333).value(), (Rate{120, 1}));
  EXPECT_EQ(rate_from_frame_time(0.033333).value(), (Rate{30, 1}));
  EXPECT_EQ(rate_from_frame_time(0.0333333).value(), (Rate{30, 1}));
  EXPECT_EQ(rate_from_frame_time(0.01).value(), (Rate{100, 1}));
  EXPECT_EQ(rate_from_frame_time(0.04).value(), (Rate{25, 1}));
  EXPECT_EQ(rate_from_frame_time(0.016667).value(), (Rate{60, 1}));
  EXPECT_EQ(rate_from_frame_time(1.0 / 24.0).value(), (Rate{24, 1}));
  EXPECT_EQ(rate_from_frame_time(0.033367).value(), (Rate{30000, 1001}));
  EXPECT_EQ(rate_from_frame_time(0.041708).value(), (Rate{24000, 1001}));
  EXPECT_EQ(rate_from_frame_time(1001.0 / 60000.0).value(), (Rate{60000, 1001}));
  // Not a common rate within its precision: the printed decimal is the period.
  // 0.012345: 1/81 = 0.01234568 is 6.8e-7 away, more than half a unit in the 6th place.
  EXPECT_EQ(rate_from_frame_time(0.012345).value(), (Rate{200000, 2469}));
  // Five decimals: 1/120 = 0.0083333 is within ±5e-6 of 0.00833.
  EXPECT_EQ(rate_from_frame_time(0.00833).value(), (Rate{120, 1}));
  // 0.0084 (±5e-5) is not 1/120 (6.7e-5 away) but 1/119 (3.4e-6 away).
  EXPECT_EQ(rate_from_frame_time(0.0084).value(), (Rate{119, 1}));
  EXPECT_FALSE(rate_from_frame_time(0.0).ok());
  EXPECT_FALSE(rate_from_frame_time(-0.01).ok());
  EXPECT_FALSE(rate_from_frame_time(NAN).ok());
}

// Computed rates (1/ticks-per-second in float, a float grid's step) are the integer
// or NTSC rate within float precision: assimp's FBX NTSC 29.9700262 Hz is 30000/1001.
TEST(Sampling, ComputedRatesAreRecognizedWithinFloatPrecision) {
  EXPECT_EQ(recognize_rate(29.9700262, kComputedRateTolerance), (Rate{30000, 1001}));
  EXPECT_EQ(recognize_rate(59.94005994, kComputedRateTolerance), (Rate{60000, 1001}));
  EXPECT_EQ(recognize_rate(60.00001, kComputedRateTolerance), (Rate{60, 1}));
  EXPECT_EQ(recognize_rate(1.0 / static_cast<double>(static_cast<float>(1.0 / 60.0)), kComputedRateTolerance), (Rate{60, 1}));
  EXPECT_FALSE(recognize_rate(59.99, kComputedRateTolerance));
  EXPECT_FALSE(recognize_rate(29.97, kComputedRateTolerance));  // 2997/100 is not NTSC: 1e-6 apart
  EXPECT_EQ(*rate_from_frame_time(1.0 / 29.9700262), (Rate{30000, 1001}));
  EXPECT_EQ(*rate_from_frame_time(1.0 / static_cast<float>(120.0)), (Rate{120, 1}));
}

TEST(Sampling, SampleTimesComeFromIntegersAndMeetSourceFramesExactly) {
  // 120 → 30: output k is bit-identical to source frame 4k.
  const Rate src{120, 1}, dst{30, 1};
  for (std::int64_t k = 0; k < 100000; ++k) ASSERT_EQ(dst.time_of(k), src.time_of(4 * k)) << k;
  // The same with a non-zero start.
  TimeGrid a{1.25, 0.0, 1e9, src, 400001}, b{1.25, 0.0, 1e9, dst, 100001};
  for (std::size_t k = 0; k < b.count; k += 997) ASSERT_EQ(b.time(k), a.time(4 * k));
  // 60 → 30000/1001 never meets except at 0, but k/HZ is the nearest double.
  const Rate ntsc{30000, 1001};
  EXPECT_DOUBLE_EQ(ntsc.time_of(30000), 1001.0);
  // Accumulating dt drifts; k/HZ does not.
  double acc = 0.0;
  for (int k = 0; k < 100000; ++k) acc += 1.0 / 120.0;
  EXPECT_GT(std::abs(acc - src.time_of(100000) ), 1e-12);
  EXPECT_EQ(src.time_of(100000), 100000.0 / 120.0);
}

struct CountCase {
  const char* src;
  const char* dst;
  std::size_t frames;
  std::size_t expected;
};

TEST(Sampling, FrameCountsFollowFloorOfDurationTimesRatePlusOne) {
  const CountCase cases[] = {
      {"120", "30", 2752, 688},     // 2751/120 s · 30 = 687.75
      {"120", "30", 2753, 689},     // exactly 688 → 689 samples
      {"120", "50", 2752, 1147},    // 22.925 s · 50 = 1146.25
      {"30", "24", 195, 156},       // 6.4667 s · 24 = 155.2
      {"30", "24", 196, 157},       // 6.5 s · 24 = 156 exactly
      {"24", "60", 49, 121},        // 2 s · 60 = 120
      {"60", "59.94", 601, 600},    // 10 s · 59.94 = 599.4
      {"60", "30000/1001", 601, 300},  // 10 s · 29.97 = 299.7
      {"30000/1001", "60000/1001", 100, 199},
      {"30", "30", 195, 195},
  };
  for (const CountCase& c : cases) {
    const Rate s = rate(c.src), d = rate(c.dst);
    EXPECT_EQ(sample_count(c.frames, s, d), c.expected) << c.src << " → " << c.dst << " over " << c.frames;
    // The floating form agrees (the 1e-9 keeps exact multiples).
    EXPECT_EQ(sample_count(s.time_of(static_cast<std::int64_t>(c.frames) - 1), d), c.expected)
        << c.src << " → " << c.dst;
    // The last sample never lies past the clip.
    const double duration = s.time_of(static_cast<std::int64_t>(c.frames) - 1);
    EXPECT_LE(d.time_of(static_cast<std::int64_t>(c.expected) - 1), duration + 1e-12);
    EXPECT_GT(d.time_of(static_cast<std::int64_t>(c.expected)), duration);
  }
}

TEST(Sampling, GridIsClampedToTheClipEnd) {
  TimeGrid g{0.0, 0.0, 1.0, Rate{3, 1}, 4};  // 0, 1/3, 2/3, 1
  EXPECT_EQ(g.time(3), 1.0);
  g.end = 0.9;
  EXPECT_EQ(g.time(3), 0.9);
  g.offset = 0.5;
  g.end = 10;
  EXPECT_DOUBLE_EQ(g.time(1), 0.5 + 1.0 / 3.0);
}
