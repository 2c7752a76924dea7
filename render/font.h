// TrueType text for titles (private to render/): a Latin-1 glyph atlas packed
// with stb_truetype at one pixel height, and the quads that draw a string.
#pragma once

#include "rotinterp/core/result.h"

#include <stb_truetype.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <iterator>
#include <vector>

namespace rotinterp::render::detail {

// The font file's bytes, read once.
struct FontFile {
  std::vector<unsigned char> data;
  stbtt_fontinfo info{};
  static Result<std::shared_ptr<const FontFile>> load(const std::filesystem::path& path);
};

// One textured quad in pixels (y downwards) with atlas coordinates.
struct GlyphQuad {
  float x0, y0, x1, y1;
  float s0, t0, s1, t1;
};

class FontAtlas {
 public:
  static constexpr int kFirst = 32;   // ' '
  static constexpr int kCount = 224;  // through U+00FF
  // Beyond Latin-1, the few the pictures write: ≥ (a saturated scale), … and —.
  static constexpr int kExtra[] = {0x2265, 0x2026, 0x2014};
  static constexpr int kGlyphs = kCount + static_cast<int>(std::size(kExtra));

  // Packs the glyphs at `pixel_height` (the font's ascent − descent in pixels).
  static Result<FontAtlas> build(std::shared_ptr<const FontFile> font, int pixel_height);

  int pixel_height() const { return pixel_height_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& bitmap() const { return bitmap_; }
  float ascent() const { return ascent_; }  // pixels above the baseline

  // Width in pixels of `utf8` (advance of the whole string).
  float text_width(std::string_view utf8) const;
  // Quads for `utf8` with the baseline starting at (x, baseline).
  std::vector<GlyphQuad> layout(std::string_view utf8, float x, float baseline) const;

 private:
  std::shared_ptr<const FontFile> font_;
  int pixel_height_ = 0;
  int width_ = 0, height_ = 0;
  float ascent_ = 0;
  std::vector<std::uint8_t> bitmap_;
  std::vector<stbtt_packedchar> chars_;
};

// The atlas' glyph of each code point of a UTF-8 string: Latin-1 and kExtra; anything
// else is '?'.
std::vector<int> glyph_indices(std::string_view utf8);

}  // namespace rotinterp::render::detail
