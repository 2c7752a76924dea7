// An 8-bit RGB image and writing it as PNG.
#pragma once

#include "rotinterp/core/result.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rotinterp::render {

// Row-major, top row first, 3 bytes (R, G, B) per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0) {}
  std::uint8_t* pixel(int x, int y) { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
};

// Writes `image` as a PNG (stb_image_write), atomically (io/files/atomic_file.h): a
// reader never sees a partial file. The same image always gives the same bytes.
Status write_png(const Image& image, const std::filesystem::path& path);

}  // namespace rotinterp::render
