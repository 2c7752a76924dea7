// Resampling a cycle (resample --loop): the clip is one period of a repeating
// motion (clip/loop.h), every joint is rebuilt on its periodic curve
// (interp/periodic.h) and the output is again one period, closing the same way.
//
// Period and rate. The input period P (closed: last − first frame; open: one
// frame more). With an output rate R the output holds M = round(P·R) frames per
// period (at least 2), closed (M + 1 frames, the last repeating the first) or open
// (M frames) as the input. Where P·R is not whole, the rate is kept and the period
// becomes M/R: the cycle is played |M/R − P| ≤ half an output frame faster or slower
// (output frame k is the source at t₀ + k·P/M). The report states it.
// With keep_every N: keys at source frames 0, N, 2N, … inside the period, then
// the wrap-around to frame 0 one period later; every source frame is rebuilt.
//
// Joints that miss closure (LoopCheck::misses, a pop in the source) are rebuilt on
// the ordinary, non-periodic curve through all their frames: their pop is kept
// and reported, not smoothed.
//
// Translation loops with its per-cycle offset D (clip/loop.h): p(t) = r(t) + D·(t − t₀)/P
// with r periodic, r interpolated on the unrolled cycle with options.translation;
// a run keeps its forward motion.
#pragma once

#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/resample.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

struct CycleResample {
  Clip clip;
  LoopCheck check;                    // the input's cycle check (form, period, misses)
  std::size_t period_frames = 0;      // output frames per period
  double period = 0.0;                // output period, seconds
  double stretch = 0.0;               // output period / input period − 1 (0 where P·R is whole)
  std::vector<std::string> not_looped;  // joints that miss closure, rebuilt with their ends
  // "cycle (closed form): 38 → 76 frames per period of 1.267 s" and, where it applies,
  // "period +0.40% (1.272 s) for whole frames at the rate asked; 1 joint misses closure (a pop at
  // the seam in the source): L_Arm 4.39°, kept as it is".
  std::string summary() const;
};

// Errors: those of resample_clip, check_loop, a --range with a loop, a clip that is
// not a cycle where `form` is unset (auto-detection: the message says why).
Result<CycleResample> resample_cycle(const Clip& clip, const ResampleOptions& options,
                                     std::optional<LoopForm> form = std::nullopt, const LoopTolerance& tolerance = {});

}  // namespace rotinterp
