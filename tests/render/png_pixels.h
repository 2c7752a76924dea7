// Reading rendered PNGs back in the renderer tests (stb_image), and the fresh
// directories they are written to.
#pragma once

#include "rotinterp/render/layout.h"

#include <stb_image.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

namespace rotinterp::test {

// A path for a test's output, unique to the test (`tag`) and the process, removed if it exists.
inline std::filesystem::path fresh_dir(const std::string& tag) {
  const auto dir = std::filesystem::temp_directory_path() / ("rotinterp_test_render_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

struct Pixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  bool ok() const { return width > 0; }
};

inline Pixels read_png(const std::filesystem::path& path) {
  Pixels p;
  int channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &p.width, &p.height, &channels, 3);
  if (!data) return Pixels{};
  p.rgb.assign(data, data + static_cast<std::size_t>(p.width) * p.height * 3);
  stbi_image_free(data);
  return p;
}

// The pixels of `r`, row by row.
inline std::vector<std::uint8_t> crop(const Pixels& p, const render::Rect& r) {
  std::vector<std::uint8_t> out;
  for (int y = r.y; y < r.y + r.height; ++y) {
    const auto* row = p.rgb.data() + (static_cast<std::size_t>(y) * p.width + r.x) * 3;
    out.insert(out.end(), row, row + 3 * r.width);
  }
  return out;
}

inline std::size_t distinct_colours(const std::vector<std::uint8_t>& rgb) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
    colours.insert((std::uint32_t(rgb[i]) << 16) | (std::uint32_t(rgb[i + 1]) << 8) | rgb[i + 2]);
  return colours.size();
}

inline std::size_t differing_pixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
    n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
  return n;
}

}  // namespace rotinterp::test
