// eval --loop: a clip evaluated as one period of a cycle (clip/loop.h), and the
// figures of its seam next to the same figures inside.
//
// Keys. With keep_every N, a joint that closes takes its keys at frames 0, N, 2N, …
// inside the period and wraps to frame 0 one period later (as resample --loop does);
// each method is rebuilt on its periodic curve (interp/periodic.h), so every frame,
// the last one too, is measured on the curve an engine plays in a loop. A joint
// that misses closure (a pop in the source) is rebuilt on its ordinary curve from
// every Nth frame and the last, as without --loop: its pop is kept, and shows at the seam.
//
// The seam figures of one joint (radians), next to the same figures inside:
//  * seam angle: the largest angle error at the frames of the two key intervals that
//    meet at the seam (the first of the period and the last); inner angle: the
//    largest at the other frames;
//  * seam velocity and acceleration jump: one-sided stencils (clip/metrics.h
//    one_sided_jumps, step kKeyJumpStep × the shorter of those two intervals) before
//    the end of the period and after its start, as an engine plays the cycle end to
//    start; inside, key_jumps over the other keys (errors.csv vel_jump_max_dps, acc_jump_max_dps2).
// A curve that is not periodic is played the same way: its last key, then its first
// (the seam of the closed form).
#pragma once

#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/interp/interpolator.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

struct ClipReference;  // eval/evaluate_clip.h
struct ErrorRow;       // eval/error_row.h

// The cycle a clip is evaluated as.
struct CycleFrames {
  LoopCheck check;           // form, period (seconds), period_frames, joints that miss closure
  std::vector<bool> looped;  // [joint]: closes, so rebuilt on its periodic curve
};

// The cycle of `clip` in `form`, or in the form detected (nullopt). Errors (one
// line): those of check_loop, and a clip that does not look like a cycle when the
// form is detected (as resample --loop).
Result<CycleFrames> cycle_frames(const Clip& clip, std::optional<LoopForm> form);

// One joint rebuilt from every keep_every-th frame.
struct RebuiltJoint {
  RotationTrack keys;
  std::unique_ptr<Interpolator> curve;
  bool periodic = false;
  // The key times key_jumps reads: its interior keys are the keys inside, not the seam
  // (periodic: the keys, then frame 0 one period later; otherwise the keys).
  std::vector<double> jump_times;
};

// With reference.cycle, as above; without, every keep_every-th frame and the last,
// on the ordinary curve (eval without --loop). Errors: the method's.
Result<RebuiltJoint> rebuild_joint(const ClipReference& reference, std::size_t joint, const std::string& method,
                                   int keep_every);

// The frames where the keys of keep_every N lie (per_frame.csv's `key`): without a
// cycle every Nth and the last; with one, the period's and the wrap-around frame at
// t₀ + P where the clip has it (the closed form's last frame).
std::vector<std::size_t> key_frames(const ClipReference& reference, int keep_every);

struct SeamFigures {
  double angle = 0.0, inner_angle = 0.0;  // rad
  KeyJumps jumps;                         // at the seam: rad/s, rad/s²
};
SeamFigures seam_figures(const ClipReference& reference, std::size_t joint, const RebuiltJoint& rebuilt);

// A joint row's seam columns (ErrorRow::seam …), from seam_figures.
void fill_seam_columns(ErrorRow& row, const ClipReference& reference, std::size_t joint, const RebuiltJoint& rebuilt);

}  // namespace rotinterp
