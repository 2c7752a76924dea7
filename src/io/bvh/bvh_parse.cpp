// BVH text into a BvhFile: the header (bvh_header.cpp), then every data row,
// validated, in double.
#include "bvh_text.h"
#include "rotinterp/io/files/huge_pages.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace rotinterp {

namespace bvh_text {

bool parse_double(std::string_view token, double& out) {
  // Fast path for what BVH data rows hold: [-]digits[.digits], at most 15 digits.
  // The digits make an integer m < 10¹⁵ < 2⁵³ and the point a power 10ᵏ (k ≤ 15),
  // both exact doubles, so m / 10ᵏ is one correctly rounded division: the same
  // value std::from_chars gives (Clinger's fast path).
  {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const char* p = token.data();
    const char* const end = p + token.size();
    const bool negative = p < end && *p == '-';
    if (negative) ++p;
    std::uint64_t m = 0;
    int digits = 0, decimals = 0;
    const char* const first = p;
    while (p < end && *p >= '0' && *p <= '9') m = m * 10 + static_cast<unsigned>(*p++ - '0'), ++digits;
    if (p > first && p < end && *p == '.') {
      ++p;
      while (p < end && *p >= '0' && *p <= '9') m = m * 10 + static_cast<unsigned>(*p++ - '0'), ++digits, ++decimals;
    }
    if (p == end && p > first && digits <= 15) {
      const double v = static_cast<double>(m) / kPow10[decimals];
      out = negative ? -v : v;
      return true;
    }
  }
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size();
}

std::string excerpt(std::string_view t) {
  std::size_t n = std::min(t.size(), kExcerptBytes);
  if (n < t.size())
    while (n > 0 && (static_cast<unsigned char>(t[n]) & 0xC0) == 0x80) --n;  // not inside a character
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(t[i]);
    if (c < 0x20 || c == 0x7F) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    } else {
      out += static_cast<char>(c);
    }
  }
  if (n < t.size()) out += "… (" + std::to_string(t.size()) + " bytes)";
  return out;
}

}  // namespace bvh_text

using namespace bvh_text;

Result<BvhFile> parse_bvh(std::string_view text, const std::string& label) {
  // Text encodings: a UTF-8 byte order mark is skipped; UTF-16 (a BOM, or the NUL
  // bytes of ASCII text in it) is named rather than quoted.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF" ||
      (text.size() >= 2 && (text[0] == '\0' || text[1] == '\0')))
    return make_error(label + ": the file is UTF-16 text; BVH is read as UTF-8 or ASCII");
  BvhFile file;
  const Result<DataStart> start = parse_header(text, label, file);
  if (!start) return start.failure();

  // Data rows: one frame per non-blank line, exactly `columns` values each.
  std::size_t pos = start->position;
  int line = start->line;
  // The rest of the Frame Time line must be blank.
  auto line_end = [&](std::size_t from) {
    const std::size_t e = text.find('\n', from);
    return e == std::string_view::npos ? text.size() : e;
  };
  {
    const std::size_t e = line_end(pos);
    for (std::size_t i = pos; i < e; ++i)
      if (!is_space(text[i]))
        return make_error(label + ": line " + std::to_string(line) + ": unexpected text after the Frame Time");
    pos = e;
  }
  // Reserve by what the text can hold, never by the declared count.
  const std::size_t max_rows_in_text = static_cast<std::size_t>(std::count(text.begin() + pos, text.end(), '\n')) + 1;
  file.values.reserve(std::min(file.frames, max_rows_in_text) * file.columns);
  advise_huge_pages(file.values.data(), file.values.capacity() * sizeof(double));

  // Which joint/channel owns each column, for messages.
  std::vector<std::pair<std::size_t, std::size_t>> owner(file.columns);
  for (std::size_t j = 0; j < file.joints.size(); ++j)
    for (std::size_t c = 0; c < file.joints[j].channels.size(); ++c) owner[file.joints[j].first_column + c] = {j, c};

  // Messages are built only on failure: this loop runs once per value (millions).
  auto where = [&](std::size_t at_frame, int at_line) {
    return label + ": frame " + std::to_string(at_frame) + " (line " + std::to_string(at_line) + ")";
  };
  auto what = [&](std::size_t column) {
    const auto [joint, channel] = owner[column];
    return "joint '" + excerpt(file.joints[joint].name) + "' " + channel_name(file.joints[joint].channels[channel]);
  };
  const char* const end = text.data() + text.size();
  const char* p = text.data() + pos;
  std::size_t frame = 0;
  while (p < end) {
    ++p;  // past '\n'
    ++line;
    // Values up to the end of the line; '\n' is the only line break.
    while (p < end && *p != '\n' && is_space(*p)) ++p;
    if (p == end || *p == '\n') continue;  // blank line
    if (frame == file.frames) {
      ++file.extra_rows;
      const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
      p = nl ? static_cast<const char*>(nl) : end;
      continue;
    }
    std::size_t n = 0;
    while (p < end && *p != '\n') {
      const char* q = p;
      while (q < end && !is_space(*q)) ++q;
      const std::string_view token(p, static_cast<std::size_t>(q - p));
      if (n >= file.columns)
        return make_error(where(frame, line) + ": more than the " + std::to_string(file.columns) +
                          " values the HIERARCHY declares");
      double v = 0.0;
      if (!parse_double(token, v))
        return make_error(where(frame, line) + ", " + what(n) + ": not a number: '" + excerpt(token) + "'");
      if (!std::isfinite(v))
        return make_error(where(frame, line) + ", " + what(n) + ": value is " + excerpt(token) + " (not finite)");
      file.values.push_back(v);
      ++n;
      p = q;
      while (p < end && *p != '\n' && is_space(*p)) ++p;
    }
    if (n != file.columns)
      return make_error(label + ": frame " + std::to_string(frame) + " (line " + std::to_string(line) + ") has " +
                        std::to_string(n) + " values, the HIERARCHY declares " + std::to_string(file.columns));
    ++frame;
  }
  if (frame < file.frames)
    return make_error(label + ": 'Frames: " + std::to_string(file.frames) + "' but the file has only " +
                      std::to_string(frame) + (frame == 1 ? " data row" : " data rows"));
  return file;
}

}  // namespace rotinterp
