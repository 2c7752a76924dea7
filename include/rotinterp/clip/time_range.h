// A time range of a clip, as --range gives it: bounds from the first frame in seconds
// or in frames, and the range in seconds on a given clip (resample_clip cuts by it).
#pragma once

#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/result.h"

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace rotinterp {

// A time range measured from the clip's first frame (0 = first frame), each bound
// in seconds or, when its *_in_frames is set, in source frames (whole numbers,
// turned into seconds with the clip's exact rate). end = +∞ means "to the clip's end".
struct TimeRange {
  double start = 0.0;
  double end = std::numeric_limits<double>::infinity();
  bool start_in_frames = false;
  bool end_in_frames = false;
};

// "START:END" (the --range text): each side empty, seconds ("1.5", "1.5s") or frames
// ("120f"); mixed forms are allowed ("2:480f"). Errors (one line, naming the text):
// no colon, a side that is neither, a negative bound, a fractional frame, END not after
// START when both are in one unit.
Result<TimeRange> parse_time_range(std::string_view text);

// `range` in seconds from the first frame of a clip `duration` seconds long (frames
// counted at `rate`), clamped to [0, duration] within round-off. Errors (one line,
// "range START:END …"): bounds in frames without a rate, a start before the first
// frame, an end past the clip's (given in seconds and frames), an empty range.
Result<std::pair<double, double>> range_seconds(const TimeRange& range, const std::optional<Rate>& rate,
                                                double duration);
// A time in seconds as messages write it (the range's errors, the importer's deadline),
// 6 significant digits ("2.5").
std::string seconds_text(double s);

}  // namespace rotinterp
