// font: the glyph atlas (Latin-1 and a few more) and the quads that draw a string.
#include "font.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace rotinterp::render::detail {

Result<std::shared_ptr<const FontFile>> FontFile::load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(path.string() + ": cannot open the font (install fonts-dejavu-core)");
  auto font = std::make_shared<FontFile>();
  font->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (font->data.empty() || !stbtt_InitFont(&font->info, font->data.data(), stbtt_GetFontOffsetForIndex(font->data.data(), 0)))
    return make_error(path.string() + ": not a TrueType font");
  return std::shared_ptr<const FontFile>(std::move(font));
}

std::vector<int> glyph_indices(std::string_view s) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    int cp = '?';
    std::size_t len = 1;
    if (c < 0x80) {
      cp = c;
    } else if ((c & 0xE0) == 0xC0 && i + 1 < s.size()) {
      cp = ((c & 0x1F) << 6) | (static_cast<unsigned char>(s[i + 1]) & 0x3F);
      len = 2;
    } else if ((c & 0xF0) == 0xE0 && i + 2 < s.size()) {
      cp = ((c & 0x0F) << 12) | ((static_cast<unsigned char>(s[i + 1]) & 0x3F) << 6) |
           (static_cast<unsigned char>(s[i + 2]) & 0x3F);
      len = 3;
    } else if ((c & 0xF8) == 0xF0) {
      len = 4;
    }
    int glyph = '?' - FontAtlas::kFirst;
    if (cp >= FontAtlas::kFirst && cp < FontAtlas::kFirst + FontAtlas::kCount) glyph = cp - FontAtlas::kFirst;
    for (int e = 0; e < static_cast<int>(std::size(FontAtlas::kExtra)); ++e)
      if (cp == FontAtlas::kExtra[e]) glyph = FontAtlas::kCount + e;
    out.push_back(glyph);
    i += len;
  }
  return out;
}

Result<FontAtlas> FontAtlas::build(std::shared_ptr<const FontFile> font, int pixel_height) {
  FontAtlas atlas;
  atlas.font_ = std::move(font);
  atlas.pixel_height_ = pixel_height;
  atlas.chars_.resize(kGlyphs);
  // 2×2 oversampling: sharper glyphs at fractional positions. The atlas grows until
  // everything fits.
  for (int side = 128; side <= 4096; side *= 2) {
    atlas.width_ = atlas.height_ = side;
    atlas.bitmap_.assign(static_cast<std::size_t>(side) * side, 0);
    stbtt_pack_context pack;
    if (!stbtt_PackBegin(&pack, atlas.bitmap_.data(), side, side, 0, 1, nullptr)) continue;
    stbtt_PackSetOversampling(&pack, 2, 2);
    int extra[std::size(kExtra)];
    std::copy(std::begin(kExtra), std::end(kExtra), extra);
    stbtt_pack_range ranges[2] = {};
    ranges[0].font_size = ranges[1].font_size = static_cast<float>(pixel_height);
    ranges[0].first_unicode_codepoint_in_range = kFirst;
    ranges[0].num_chars = kCount;
    ranges[0].chardata_for_range = atlas.chars_.data();
    ranges[1].array_of_unicode_codepoints = extra;
    ranges[1].num_chars = static_cast<int>(std::size(kExtra));
    ranges[1].chardata_for_range = atlas.chars_.data() + kCount;
    const int ok = stbtt_PackFontRanges(&pack, atlas.font_->data.data(), 0, ranges, 2);
    stbtt_PackEnd(&pack);
    if (ok) {
      int ascent = 0, descent = 0, gap = 0;
      stbtt_GetFontVMetrics(&atlas.font_->info, &ascent, &descent, &gap);
      atlas.ascent_ = static_cast<float>(ascent) * stbtt_ScaleForPixelHeight(&atlas.font_->info, static_cast<float>(pixel_height));
      return atlas;
    }
  }
  return make_error("font: glyphs at " + std::to_string(pixel_height) + " px do not fit a 4096² atlas");
}

float FontAtlas::text_width(std::string_view utf8) const {
  float width = 0;
  for (int g : glyph_indices(utf8)) width += chars_[static_cast<std::size_t>(g)].xadvance;
  return width;
}

std::vector<GlyphQuad> FontAtlas::layout(std::string_view utf8, float x, float baseline) const {
  std::vector<GlyphQuad> quads;
  // Snap the pen to whole pixels: identical strings at identical positions give
  // identical pixels, and the text stays crisp.
  float px = std::round(x);
  float py = std::round(baseline);
  for (int g : glyph_indices(utf8)) {
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(chars_.data(), width_, height_, g, &px, &py, &q, 0);
    if (g != ' ' - kFirst) quads.push_back(GlyphQuad{q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1});
  }
  return quads;
}

}  // namespace rotinterp::render::detail
