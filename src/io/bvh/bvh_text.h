// What the passes over BVH text share (bvh_header.cpp, bvh_parse.cpp): whitespace,
// numbers, excerpts for messages, and the pass over everything before the data rows.
// Private to src/io.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/bvh/bvh.h"

#include <cstddef>
#include <string>
#include <string_view>

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

}  // namespace rotinterp::bvh_text
