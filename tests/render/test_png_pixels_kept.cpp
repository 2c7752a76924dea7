// The PNG writer is lossless whatever its deflate level: what write_png writes
// reads back as the very pixels it was given (the level changes bytes only).
#include "png_pixels.h"

#include "rotinterp/render/image.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

namespace rotinterp::render {
namespace {

TEST(PngPixels, AWrittenPngReadsBackAsExactlyThePixelsWritten) {
  // Flat runs (a background), a gradient and pseudo-random noise: the long matches,
  // the short ones and the literals of deflate, and every value of the "up" filter.
  Image image(257, 131);
  std::uint32_t state = 12345;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      state = state * 1664525u + 1013904223u;
      const bool noise = y > 80, flat = x < 100;
      for (int c = 0; c < 3; ++c)
        p[c] = noise ? static_cast<std::uint8_t>(state >> (8 * c + 8))
                     : flat ? static_cast<std::uint8_t>(40 + 60 * c) : static_cast<std::uint8_t>(x + y * c);
    }
  const auto dir = test::fresh_dir("png_pixels");
  std::filesystem::create_directories(dir);
  const auto path = dir / "kept.png";
  ASSERT_TRUE(write_png(image, path).ok());
  const test::Pixels back = test::read_png(path);
  ASSERT_EQ(back.width, image.width);
  ASSERT_EQ(back.height, image.height);
  EXPECT_TRUE(back.rgb == image.rgb);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
