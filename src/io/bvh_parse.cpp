// BVH text into a BvhFile: the header (bvh_header.cpp), then every data row,
// validated, in double.
#include "bvh_text.h"
#include "huge_pages.h"

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

Result<RowCursor> read_to_rows(std::string_view text, const std::string& label, BvhFile& file) {
  // Text encodings: a UTF-8 byte order mark is skipped; UTF-16 (a BOM, or the NUL
  // bytes of ASCII text in it) is named rather than quoted.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF" ||
      (text.size() >= 2 && (text[0] == '\0' || text[1] == '\0')))
    return make_error(label + ": the file is UTF-16 text; BVH is read as UTF-8 or ASCII");
  const Result<DataStart> start = parse_header(text, label, file);
  if (!start) return start.failure();
  RowCursor c{text.data() + start->position, text.data() + text.size(), start->line};
  const char* const rest = c.p;
  skip_rest_of_row(c);
  for (const char* i = rest; i < c.p; ++i)
    if (!is_space(*i))
      return make_error(label + ": line " + std::to_string(c.line) + ": unexpected text after the Frame Time");
  return c;
}

RowParser::RowParser(const BvhFile& file, const std::string& label) : file_(file), label_(label), owner_(file.columns) {
  for (std::size_t j = 0; j < file.joints.size(); ++j)
    for (std::size_t c = 0; c < file.joints[j].channels.size(); ++c) owner_[file.joints[j].first_column + c] = {j, c};
}

// Messages are built only on failure: parse() runs once per value (millions).
std::string RowParser::where(std::size_t frame, int line) const {
  return label_ + ": frame " + std::to_string(frame) + " (line " + std::to_string(line) + ")";
}

std::string RowParser::what(std::size_t column) const {
  const auto [joint, channel] = owner_[column];
  return "joint '" + excerpt(file_.joints[joint].name) + "' " + channel_name(file_.joints[joint].channels[channel]);
}

Status RowParser::parse(RowCursor& c, std::size_t frame, double* row) const {
  const char* const end = c.end;
  const char* p = c.p;
  std::size_t n = 0;
  while (p < end && *p != '\n') {
    const char* q = p;
    while (q < end && !is_space(*q)) ++q;
    const std::string_view token(p, static_cast<std::size_t>(q - p));
    if (n >= file_.columns)
      return make_error(where(frame, c.line) + ": more than the " + std::to_string(file_.columns) +
                        " values the HIERARCHY declares");
    double v = 0.0;
    if (!parse_double(token, v))
      return make_error(where(frame, c.line) + ", " + what(n) + ": not a number: '" + excerpt(token) + "'");
    if (!std::isfinite(v))
      return make_error(where(frame, c.line) + ", " + what(n) + ": value is " + excerpt(token) + " (not finite)");
    row[n++] = v;
    p = q;
    while (p < end && *p != '\n' && is_space(*p)) ++p;
  }
  c.p = p;
  if (n != file_.columns)
    return make_error(label_ + ": frame " + std::to_string(frame) + " (line " + std::to_string(c.line) + ") has " +
                      std::to_string(n) + " values, the HIERARCHY declares " + std::to_string(file_.columns));
  return Ok{};
}

}  // namespace bvh_text

using namespace bvh_text;

Result<BvhFile> parse_bvh(std::string_view text, const std::string& label) {
  BvhFile file;
  const Result<RowCursor> rows = read_to_rows(text, label, file);
  if (!rows) return rows.failure();
  // Reserve by what the text can hold, never by the declared count.
  file.values.reserve(std::min(file.frames, max_rows(*rows, file.columns)) * file.columns);
  advise_huge_pages(file.values.data(), file.values.capacity() * sizeof(double));
  const RowParser parser(file, label);
  auto append = [&](std::size_t, const double* row) { file.values.insert(file.values.end(), row, row + file.columns); };
  if (Status s = read_rows(*rows, 0, file.frames, parser, append, file.extra_rows); !s) return s.failure();
  return file;
}

}  // namespace rotinterp
