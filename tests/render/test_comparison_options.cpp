// Parsing --frames/--size and choosing frames: no GL, no interpolators.
#include "synthetic_clip.h"

#include "rotinterp/render/comparison.h"
#include "rotinterp/render/option_text.h"

#include <gtest/gtest.h>

namespace rotinterp::render {
namespace {

TEST(FrameRange, AcceptsStartEndStepAndShorterForms) {
  auto r = parse_frame_range("120:240:10");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->start, 120u);
  EXPECT_EQ(r->end, 240u);
  EXPECT_EQ(r->step, 10u);
  r = parse_frame_range("7");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->start, 7u);
  EXPECT_EQ(r->end, 7u);
  r = parse_frame_range("3:9");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->step, 1u);
}

TEST(FrameRange, RejectsMalformedRangesWithOneLine) {
  for (const char* bad : {"", "a", "1:2:3:4", "5:2", "1:9:0", "-1:5", "1:5:x", "1.5:3"}) {
    auto r = parse_frame_range(bad);
    EXPECT_FALSE(r.ok()) << bad;
    if (!r.ok()) {
      EXPECT_EQ(r.error().find('\n'), std::string::npos);
    }
  }
}

TEST(Size, ParsesWxHAndRejectsTheRest) {
  auto s = parse_size("960x540");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->first, 960);
  EXPECT_EQ(s->second, 540);
  EXPECT_TRUE(parse_size("64X48").ok());
  for (const char* bad : {"960", "x540", "960x", "0x10", "-5x5", "12ax5", "99999999999x2"}) EXPECT_FALSE(parse_size(bad).ok()) << bad;
}

TEST(ComparisonFrames, ExplicitRangeIncludesEndAndIsCheckedAgainstTheClip) {
  const Clip clip = test::synthetic_clip(61);
  ComparisonOptions o;
  o.frames = FrameRange{10, 30, 10};
  auto frames = comparison_frames(clip, o);
  ASSERT_TRUE(frames.ok());
  EXPECT_EQ(*frames, (std::vector<std::size_t>{10, 20, 30}));
  o.frames = FrameRange{50, 61, 1};
  frames = comparison_frames(clip, o);
  ASSERT_FALSE(frames.ok());
  EXPECT_NE(frames.error().find("runs past the clip's end (ends at frame 60"), std::string::npos) << frames.error();
}

TEST(ComparisonFrames, DefaultIsEightFramesHalfwayBetweenKeys) {
  const Clip clip = test::synthetic_clip(201);
  ComparisonOptions o;
  o.keep_every = 10;  // keys 0, 10, …, 200: midpoints 5, 15, …, 195
  auto frames = comparison_frames(clip, o);
  ASSERT_TRUE(frames.ok());
  ASSERT_EQ(frames->size(), 8u);
  EXPECT_EQ(frames->front(), 5u);
  EXPECT_EQ(frames->back(), 195u);
  for (std::size_t f : *frames) EXPECT_EQ(f % 10, 5u) << f;
  o.keep_every = 1;  // every frame a key: frames spread evenly
  frames = comparison_frames(clip, o);
  ASSERT_TRUE(frames.ok());
  EXPECT_EQ(frames->size(), 8u);
  EXPECT_EQ(frames->front(), 0u);
  EXPECT_EQ(frames->back(), 200u);
}

}  // namespace
}  // namespace rotinterp::render

namespace rotinterp::render {
namespace {

TEST(Backend, NamesRoundTripAndUnknownNamesListTheChoices) {
  for (Backend b : {Backend::osmesa, Backend::egl}) {
    auto parsed = parse_backend(backend_name(b));
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(*parsed, b);
  }
  auto bad = parse_backend("vulkan");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("osmesa or egl"), std::string::npos) << bad.error();
}

TEST(Backend, BothBackendsAreAvailableHereAndOSMesaIsTheDefault) {
  // This machine has Mesa 22.3 with OSMesa and the surfaceless EGL platform.
  EXPECT_TRUE(backend_available(Backend::osmesa));
  EXPECT_TRUE(backend_available(Backend::egl));
  EXPECT_EQ(default_backend(), Backend::osmesa);
}

}  // namespace
}  // namespace rotinterp::render
