// render --loop: a cycle (clip/loop.h) played twice, so the seam between its periods is seen.
//
// The clip drawn holds the frames of one period (clip/frames.h, those before t₀ + P)
// twice, time running on (t + P in the second period), and for the closed form the
// first frame once more two periods on; the second period's translations moved by
// the per-cycle offset D (clip/loop.h), so a run keeps running. Its rotations at
// frame i are the source's at frame i mod (frames per period).
//
// Keys: frames 0, N, 2N, … inside each period, then the wrap to the next period's
// frame 0. Each joint's curve is the rebuild of one period with its cycle
// (clip/rebuild.h, as eval --loop measures it); a joint that misses closure (a pop
// in the source) has its one-period curve repeated each period: its pop shows at
// the seam, as an engine plays it.
#pragma once

#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/rebuild.h"
#include "rotinterp/interp/interpolator.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::render {

// What --loop asked: the form, or nothing to detect it.
struct LoopPlay {
  std::optional<LoopForm> form;
};

struct CyclePlayedTwice {
  Clip clip;                        // the two periods
  CycleFrames cycle;                // the source's cycle, and which joints close it
  std::size_t period_frames = 0;    // frames per period in `clip`
  std::vector<std::size_t> keys;    // key frames of `clip`, sorted
  // The curve of `method` for `joint`, on `clip`'s timeline. Errors: the method's.
  Result<std::unique_ptr<Interpolator>> curve(const std::string& method, std::size_t joint) const;

  // The source's frames of one period (private to curve()).
  std::vector<double> period_times;             // [frame], seconds
  std::vector<std::vector<Quat>> period_frames_rotation;  // [joint][frame], one more for the closed form's end
  std::size_t keep_every = 1;
};

// Errors (one line): those of check_loop, a clip that does not look like a cycle
// when the form is detected, fewer than 2 frames per period.
Result<CyclePlayedTwice> play_cycle_twice(const Clip& clip, const LoopPlay& loop, std::size_t keep_every);

}  // namespace rotinterp::render
