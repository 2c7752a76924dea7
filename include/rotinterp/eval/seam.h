// eval --loop: a clip evaluated as one period of a cycle (clip/loop.h), and the
// figures of its seam next to the same figures inside.
//
// Keys and curves are clip/rebuild.h's with the cycle: every frame, the last one
// too, is measured on the curve an engine plays in a loop, and a joint that misses
// closure keeps its pop, which shows at the seam.
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

#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/rebuild.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

struct ClipReference;  // eval/evaluate_clip.h
struct ErrorRow;       // eval/error_row.h

// With reference.cycle, the rebuild of clip/rebuild.h on the cycle; without, on
// every keep_every-th frame and the last (eval without --loop). Errors: the method's.
Result<RebuiltJoint> rebuild_joint(const ClipReference& reference, std::size_t joint, const std::string& method,
                                   int keep_every);

// The frames where the keys of keep_every N lie (per_frame.csv's `key`): clip/rebuild.h
// key_frames on the reference's frames and cycle.
std::vector<std::size_t> key_frames(const ClipReference& reference, int keep_every);

struct SeamFigures {
  double angle = 0.0, inner_angle = 0.0;  // rad
  KeyJumps jumps;                         // at the seam: rad/s, rad/s²
};
SeamFigures seam_figures(const ClipReference& reference, std::size_t joint, const RebuiltJoint& rebuilt);

// A joint row's seam columns (ErrorRow::seam …), from seam_figures.
void fill_seam_columns(ErrorRow& row, const ClipReference& reference, std::size_t joint, const RebuiltJoint& rebuilt);

}  // namespace rotinterp
