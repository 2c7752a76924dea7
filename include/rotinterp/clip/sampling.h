// Exact frame rates and sample grids.
//
// Rates are kept as exact rationals (30000/1001 Hz stays 30000/1001) and sample
// times are always computed from integers, t_k = start + k·den/num, never by
// adding a frame time repeatedly (which drifts: 100 000 additions of 1/120 are off
// by ~1e-10 s each and by a visible amount for float). Two grids that meet at a
// real time meet at the same double: k/30 and 4k/120 are the correctly rounded
// quotient of the same rational, so 120 → 30 lands bit-exactly on every 4th frame.
#pragma once

#include "rotinterp/core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// A frame rate num/den in frames per second. Invariants: num > 0, den > 0,
// gcd(num, den) = 1 (make_rate reduces).
struct Rate {
  std::int64_t num = 0;
  std::int64_t den = 1;

  double hz() const { return static_cast<double>(num) / static_cast<double>(den); }
  // Seconds per frame, den/num, as the nearest double.
  double period() const { return static_cast<double>(den) / static_cast<double>(num); }
  // k·den/num seconds: one correctly rounded division of exact integers (for
  // k·den < 2⁵³), so equal rationals give equal doubles.
  double time_of(std::int64_t k) const;
  // "30", "59.94", "30000/1001".
  std::string to_string() const;
  friend bool operator==(const Rate& a, const Rate& b) { return a.num == b.num && a.den == b.den; }
  friend bool operator!=(const Rate& a, const Rate& b) { return !(a == b); }
};

// num/den reduced; an error unless both are positive.
Result<Rate> make_rate(std::int64_t num, std::int64_t den);

// Parses a rate as a decimal ("30", "59.94", "119.88") or a rational of two
// decimals ("30000/1001", "24000/1001"), exactly: "59.94" is 2997/50 Hz. Errors
// (one line, naming the text): empty, not a number, ≤ 0, more than 12 decimals
// or too large (> 1e9 Hz).
Result<Rate> parse_rate(std::string_view text);

// Relative precision of a rate computed from stored times rather than printed:
// float32 key times (glTF) and assimp's float tick rates (FBX NTSC 29.9700262 Hz)
// are good to ~6e-8; 1e-6 leaves room for a step averaged over a float grid.
constexpr double kComputedRateTolerance = 1e-6;

// The exact rate behind a rate `hz` known to `relative_tolerance`: the first of
// (1) an integer rate n = 1 … 100 000 Hz, (2) an NTSC rate n·1000/1001 within
// the tolerance; nothing otherwise.
std::optional<Rate> recognize_rate(double hz, double relative_tolerance);

// The exact rate behind a frame time read from a file. A frame time is printed with
// finite precision (BVH "Frame Time: 0.008333" is 1/120 to 6 decimals). The
// printed precision is taken from the shortest decimal that reads back as
// `frame_time` (0.008333 → 6 decimals → ±5e-7 s). Within that precision the first
// match of (1) an integer rate n = 1 … 100 000 Hz (period 1/n), (2) an NTSC rate
// n·1000/1001 (period 1001/(1000 n)) is taken; otherwise the printed decimal itself
// is the exact period (0.0123 → 10000/123 Hz). A frame time with more than 12
// decimals was computed, not printed (1/ticks-per-second, a float grid's step): it
// goes through recognize_rate(1/frame_time, kComputedRateTolerance), then to the
// simplest nearby rational. This is the one recognizer every command uses
// (clip_rate in clip/frames.h). Returns an error for frame_time ≤ 0 or not finite.
Result<Rate> rate_from_frame_time(double frame_time);

// Number of samples of a grid at `rate` over `duration` seconds, first sample at
// 0: floor(duration·rate + 1e-9) + 1 (the 1e-9 keeps an exact multiple from
// losing its last sample to round-off). 0 for a negative or non-finite duration.
std::size_t sample_count(double duration, const Rate& rate);

// Exact form for a uniformly sampled source: `frames` frames at `source` span
// (frames − 1)/source seconds; the number of samples of `target` that fit,
// floor((frames − 1)·target/source) + 1, in integer arithmetic.
std::size_t sample_count(std::size_t frames, const Rate& source, const Rate& target);

// A uniform grid of sample times: time(k) = start + offset + k/rate for
// k = 0 … count − 1, never beyond `end` (clamped — the last sample never
// extrapolates past the clip).
struct TimeGrid {
  double start = 0.0;   // seconds: the clip's first frame time
  double offset = 0.0;  // seconds after start of sample 0 (a --range start)
  double end = 0.0;     // seconds: no sample later than this
  Rate rate{1, 1};
  std::size_t count = 0;

  double time(std::size_t k) const;
  std::vector<double> times() const;
};

}  // namespace rotinterp
