#include "rotinterp/io/record/clip_file.h"

#include <cmath>
#include <utility>

namespace rotinterp {

std::size_t take_frames(const AnimationSummary& take) {
  if (!(take.frame_rate_hz > 0.0) || !(take.duration >= 0.0)) return take.keys;
  return static_cast<std::size_t>(std::llround(take.duration * take.frame_rate_hz)) + 1;
}


const char* rate_origin_text(bool stated) { return stated ? "stated by the file" : "inferred from its key times"; }

Result<ClipFileInfo> reading_or_failure(ReadOutcome outcome) {
  if (outcome.error) return make_error(std::move(*outcome.error), outcome.kind);
  return std::move(outcome.info);
}

}  // namespace rotinterp
