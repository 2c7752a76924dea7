// What the passes over BVH text share (bvh_header.cpp, bvh_parse.cpp, bvh_stream.cpp):
// whitespace, numbers, excerpts for messages, the pass over everything before the data
// rows and the one reader of the data rows. Private to src/io.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/bvh.h"

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotinterp::bvh_text {

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// A full-token double (no trailing garbage); accepts "nan"/"inf" so that the caller
// can name them.
bool parse_double(std::string_view token, double& out);

// A token or name as messages quote it: at most kExcerptBytes bytes (cut at a
// UTF-8 character boundary), control bytes as \xNN, and the full size when cut, so
// a 100 MB token gives a short line.
inline constexpr std::size_t kExcerptBytes = 40;
std::string excerpt(std::string_view t);

// Where the data rows start: the end of the Frame Time value, and its line.
struct DataStart {
  std::size_t position = 0;
  int line = 1;
};

// The HIERARCHY section and the MOTION header (Frames, Frame Time) into `file`.
// Errors start with `label` and name the line.
Result<DataStart> parse_header(std::string_view text, const std::string& label, BvhFile& file);

// A place in the data rows: `p` at the '\n' before the next line (or at the text's
// end), `line` the number of the line `p` is on. '\n' is the only line break.
struct RowCursor {
  const char* p = nullptr;
  const char* end = nullptr;
  int line = 1;
};

// Everything before the data rows: the encoding (a UTF-8 byte order mark skipped,
// UTF-16 refused), the header into `file` (parse_header), the rest of the Frame Time
// line (blank); and where the rows start.
Result<RowCursor> read_to_rows(std::string_view text, const std::string& label, BvhFile& file);

// The most data rows of `columns` values the text after `c` can hold: each row takes
// at least 2·columns bytes (the '\n' before it, one byte per value, a space between
// two), so a larger `Frames:` cannot be met, whatever the rows hold.
inline std::size_t max_rows(const RowCursor& c, std::size_t columns) {
  return columns == 0 ? 0 : static_cast<std::size_t>(c.end - c.p) / (2 * columns);
}

// Moves `c` to the next data row (the next non-blank line), `c.p` at its first
// value: false when the text ends first.
inline bool next_row(RowCursor& c) {
  while (c.p < c.end) {
    ++c.p;  // past '\n'
    ++c.line;
    while (c.p < c.end && *c.p != '\n' && is_space(*c.p)) ++c.p;
    if (c.p < c.end && *c.p != '\n') return true;
  }
  return false;
}

// Moves `c` from inside a row to the end of its line.
inline void skip_rest_of_row(RowCursor& c) {
  const void* nl = std::memchr(c.p, '\n', static_cast<std::size_t>(c.end - c.p));
  c.p = nl ? static_cast<const char*>(nl) : c.end;
}

// Moves `c` past up to `rows` data rows without reading them; how many it passed.
inline std::size_t skip_rows(RowCursor& c, std::size_t rows) {
  std::size_t n = 0;
  for (; n < rows && next_row(c); ++n) skip_rest_of_row(c);
  return n;
}

// Reads one data row into doubles, validated (exactly `columns` finite numbers); its
// messages name the frame, the line, the joint and the channel.
class RowParser {
 public:
  RowParser(const BvhFile& file, const std::string& label);
  std::size_t columns() const { return file_.columns; }
  std::size_t frames() const { return file_.frames; }  // declared
  const std::string& label() const { return label_; }
  // The row `c.p` is in (frame `frame`) into row[0, columns()); `c` ends at its
  // line's end.
  Status parse(RowCursor& c, std::size_t frame, double* row) const;

 private:
  std::string where(std::size_t frame, int line) const;
  std::string what(std::size_t column) const;

  const BvhFile& file_;
  const std::string& label_;
  std::vector<std::pair<std::size_t, std::size_t>> owner_;  // joint and channel of each column
};

// Data rows [first, last) from `c` (just before row `first`), each parsed and given
// to sink(frame, row). When `last` is the declared frame count, the rows after it
// are counted in `extra_rows`, unread. Fails at the first bad row, or when the text
// ends before row `last`: the errors of a pass over the whole file, in file order.
template <class Sink>
Status read_rows(RowCursor c, std::size_t first, std::size_t last, const RowParser& parser, Sink&& sink,
                 std::size_t& extra_rows) {
  std::vector<double> row(parser.columns());
  std::size_t frame = first;
  for (; frame < last && next_row(c); ++frame) {
    if (Status s = parser.parse(c, frame, row.data()); !s) return s;
    sink(frame, row.data());
  }
  if (frame < last)
    return make_error(parser.label() + ": 'Frames: " + std::to_string(parser.frames()) + "' but the file has only " +
                      std::to_string(frame) + (frame == 1 ? " data row" : " data rows"));
  if (last == parser.frames())
    while (next_row(c)) ++extra_rows, skip_rest_of_row(c);
  return Ok{};
}

}  // namespace rotinterp::bvh_text
