// Time ranges: the --range text, and a range in seconds on a clip.
#include "rotinterp/clip/time_range.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>

namespace rotinterp {

namespace {

// "1.5", "120f": a bound as the user wrote it.
std::string bound_text(double v, bool in_frames) { return seconds_text(v) + (in_frames ? "f" : ""); }

}  // namespace

std::string seconds_text(double s) {
  std::ostringstream os;
  os.precision(6);
  os << s;
  return os.str();
}

Result<TimeRange> parse_time_range(std::string_view text) {
  const std::string quoted = "--range '" + std::string(text) + "'";
  const std::string form = quoted + " must be START:END in seconds (1.5:4) or frames (120f:480f); either side may be empty";
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos || text.find(':', colon + 1) != std::string_view::npos) return make_error(form);
  TimeRange r;
  // One side: empty (open), seconds with an optional "s", or whole frames with "f".
  auto side = [&](std::string_view s, double& value, bool& in_frames) -> Status {
    if (s.empty()) return Ok{};
    in_frames = s.back() == 'f';
    if (in_frames || s.back() == 's') s.remove_suffix(1);
    const std::string number(s);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || errno == ERANGE || !std::isfinite(v) ||
        std::isspace(static_cast<unsigned char>(number[0])))
      return make_error(form);
    if (v < 0.0) return make_error(quoted + ": a bound cannot be negative (0 is the first frame)");
    if (in_frames && (v != std::floor(v) || v > 1e15)) return make_error(quoted + ": frames are whole numbers");
    value = v;
    return Ok{};
  };
  if (Status s = side(text.substr(0, colon), r.start, r.start_in_frames); !s) return s.failure();
  if (Status s = side(text.substr(colon + 1), r.end, r.end_in_frames); !s) return s.failure();
  if (r.start_in_frames == r.end_in_frames && !(r.end > r.start)) return make_error(quoted + ": END must be after START");
  return r;
}


Result<std::pair<double, double>> range_seconds(const TimeRange& range, const std::optional<Rate>& rate,
                                                double duration) {
  const std::string text = "range " + bound_text(range.start, range.start_in_frames) + ":" +
                           (std::isinf(range.end) ? std::string() : bound_text(range.end, range.end_in_frames));
  if ((range.start_in_frames || range.end_in_frames) && !rate)
    return make_error(text + ": the clip has no frame rate, so no frames to count; give the range in seconds");
  auto seconds = [&](double v, bool in_frames) {
    return in_frames ? rate->time_of(static_cast<std::int64_t>(v)) : v;
  };
  const double ra = seconds(range.start, range.start_in_frames);
  const double rb = std::isinf(range.end) ? duration : seconds(range.end, range.end_in_frames);
  const double slack = 1e-9 * std::max(1.0, duration);
  if (!std::isfinite(ra) || ra < -slack) return make_error(text + " starts before the clip's first frame");
  if (std::isnan(rb) || rb > duration + slack) {
    const std::string last = rate ? " / frame " + std::to_string(std::llround(duration * rate->hz())) : "";
    return make_error(text + " runs past the clip's end (ends at " + seconds_text(duration) + " s" + last + ")");
  }
  if (!(rb > ra)) return make_error(text + " is empty: END must be after START");
  return std::make_pair(std::max(0.0, ra), std::min(duration, rb));
}

}  // namespace rotinterp
