// A frame rate and a key spacing as a user gives them: --fps and --keep-every on the
// command line, fps= and keep_every= in Python. One reading for both, so that each
// refuses what the other refuses (issue 47, class 5).
#pragma once

#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/result.h"

#include <string>
#include <string_view>

namespace rotinterp {

// Largest keep-every (frames between keys: --keep-every, eval's and render's, Python's
// keep_every): far above any clip's frame count.
inline constexpr long long kMaxKeepEvery = 1000000000;

// parse_rate's forms, plus plain numbers it does not take (exponent notation: 1e3, a
// float's "1e+20"); a number out of range is called that, with the range, not "not a
// number". Errors start with `name` ("--fps '1e20' is out of range (at most 1e9 Hz)",
// "fps: frame rate 'x' is not a number …").
Result<Rate> parse_rate_value(std::string_view name, const std::string& text);

}  // namespace rotinterp
