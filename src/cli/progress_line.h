// The progress line every long job draws on stderr, in one format.
#pragma once

#include "rotinterp/core/progress.h"

#include <cstddef>
#include <string>

namespace rotinterp::cli {

// Every long job's progress line, one format: "eval  3/12 files (25%)  1.5 files/s  ETA 6s"
// (`unit` may be empty: "3/12 (25%)  1.5/s"); the rate is done over `seconds` since the
// start, the ETA the rest at that rate ("?" before the first unit is done).
std::string progress_line(const std::string& label, const std::string& unit, std::size_t done, std::size_t total,
                          double seconds);
// "42s", "1m05s", "2h03m".
std::string duration_text(double seconds);
// A progress reporter that draws progress_line on stderr (at most 10 times a second)
// when stderr is a terminal and quiet is false; otherwise an empty function. Thread-safe.
ProgressFn make_progress(std::string label, bool quiet, std::string unit = "");
// Ends the progress line (if one was drawn).
void end_progress(bool quiet);

}  // namespace rotinterp::cli
