// Resampling a clip: change its frame rate, or rebuild it from a sparse key set,
// with any registered rotation interpolator (interp/interpolator.h) per joint and
// a linear or cubic curve for translation tracks (clip/translation_curve.h).
//
// Times. A source with a frame time (BVH "Frame Time", an FBX frame rate) has its
// frame rate recognized exactly (clip/sampling.h: 0.008333 → 120 Hz), and its key
// times are moved onto that exact grid first (each key to its frame, as
// clip/frames.h assigns keys to frames), so 120 → 30 Hz lands exactly on
// every 4th source frame. Output frame k is at start + k/HZ (k/HZ from integers),
// k = 0 … floor(duration·HZ + 1e-9); it never lies past the clip's end.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/clip/time_range.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

// The default rotation method of `rotinterp resample`, chosen by measurement on
// real clips (README "rotinterp resample").
inline constexpr const char* kDefaultResampleMethod = "clamped";

struct ResampleOptions {
  // Output rate. Unset and keep_every unset: the source's own rate (a round trip
  // through the interpolators). Mutually exclusive with keep_every.
  std::optional<Rate> fps;
  // ≥ 1: keep every Nth source frame (and always the last) as keys and rebuild
  // every source frame from them. Unset: not used.
  std::optional<std::size_t> keep_every;
  // Rotation method for every joint (a name in methods()), and per-joint overrides
  // (joint name → method name), applied in order.
  std::string method = kDefaultResampleMethod;
  std::vector<std::pair<std::string, std::string>> method_for;
  TranslationInterp translation = TranslationInterp::cubic;
  // Cut this range before resampling; the output starts at the clip's start time.
  // With --fps, keys outside the range still shape the curve near the cut, so a
  // cut equals the same frames of an uncut resample. With keep_every, the first
  // and last frames inside the range are keys.
  std::optional<TimeRange> range;
  // Worker threads over joints; 0 = one per hardware thread (at most one per joint).
  unsigned threads = 0;
  // Called with (joints done, joints) from worker threads.
  ProgressFn progress;
};

// Resamples `clip` (validated first). The result is a valid clip on a uniform grid:
// every joint has one rotation key per output frame, every joint with a
// translation track one translation key per frame, sign-continuous quaternions;
// frame_time = 1/HZ for --fps, else the source's frame time, else (keys on no grid)
// the rate the file states (stated_rate_hz, clip/source_record.h) as if given as fps. Errors: both fps and
// keep_every given, keep_every < 1, no source frame rate where one is needed,
// unknown method (listing the valid names) or joint, a range that starts before the
// clip, runs past its end (the message gives the end in seconds and frames) or is empty,
// a range in frames on a clip without a frame rate.
Result<Clip> resample_clip(const Clip& clip, const ResampleOptions& options);
// The same result from a clip the caller gives up: its key arrays move into the
// output where they are kept as they are (the same rate), instead of being copied.
// `clip` is left with its tracks moved out.
Result<Clip> resample_clip(Clip&& clip, const ResampleOptions& options);

}  // namespace rotinterp
