// parse_rate_value (clip/rate_value.h).
#include "rotinterp/clip/rate_value.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace rotinterp {

Result<Rate> parse_rate_value(std::string_view name, const std::string& text) {
  auto rate = parse_rate(text);
  if (rate) return rate;
  // A finite double when all of the text is one (strtod's forms: 1e9, -30, 0x1p4).
  char* end = nullptr;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ? NAN : std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return rate.failure(std::string(name) + ": ");
  const std::string quoted = std::string(name) + " '" + text + "'";
  if (v <= 0) return make_error(quoted + " must be greater than 0");
  // In range but in a form parse_rate does not read (1e3): the same value as the
  // shortest decimal that reads back as it. Any number ≥ 1 so written reads unless
  // it is above parse_rate's limit.
  char buf[400];
  const auto printed = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  if (auto again = parse_rate(std::string_view(buf, static_cast<std::size_t>(printed.ptr - buf)))) return again;
  if (v >= 1) return make_error(quoted + " is out of range (at most 1e9 Hz)");
  return make_error(quoted + " is too small or too precise for an exact rate; use a ratio such as 1/3600");
}

}  // namespace rotinterp
