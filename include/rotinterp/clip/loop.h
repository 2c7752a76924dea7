// Cycles: whether a clip is one period of a motion that repeats, in which form, and
// which joints miss closing it.
//
// Two forms of a cycle sampled at frames 0 … n−1 (frame time Δ):
//  * closed: the last frame repeats the first (period (n−1)·Δ);
//  * open: the last frame is one step before the first (period n·Δ).
// A joint closes a form when its miss is within the angle tolerance. Closed: the
// last frame's angle from the first. Open: the step from the last frame to the
// first (one frame later) must be as smooth as the motion inside — the change of
// angular velocity at the seam beyond the largest change between frames inside,
// times one frame. The form is the one whose closure misses sum to less over all joints
// (closed on a tie), unless the caller names it.
//
// Translation loops with a per-cycle offset: each translation track moves by
// D = pₙ − p₀ every period (pₙ = pₙ₋₁ for closed; for open, the parabola through
// the last three keys one frame on), so a run keeps its forward motion. Only the root's vertical part of D must close (up =
// the longest side of the rest pose's bounding box).
//
// "Looks like a cycle": some joint moves by more than the angle tolerance, at most
// a tenth of the moving joints miss closure (a source pop in one joint does not
// hide a cycle; it is reported), and the root's vertical offset closes.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

enum class LoopForm { closed, open };
const char* loop_form_name(LoopForm form);  // "closed", "open"

struct LoopTolerance {
  double angle = 0.5 * 3.14159265358979323846 / 180.0;  // rad (0.5°): a joint's closure miss
  double root_offset = 0.01;                            // metres (1 cm): the root's vertical closure
};

// A joint whose closure misses the angle tolerance: a pop at the seam in the source.
struct ClosureMiss {
  std::size_t joint;
  std::string name;
  double angle;  // rad
};

struct LoopCheck {
  LoopForm form = LoopForm::closed;
  bool looks_like_cycle = false;
  double period = 0.0;               // seconds
  std::size_t period_frames = 0;     // frames per period (closed: n − 1, open: n)
  double worst_closing_angle = 0.0;  // rad: the largest miss among joints that close
  std::vector<ClosureMiss> misses;   // joints that miss, largest first
  std::size_t moving_joints = 0;     // joints turning by more than the angle tolerance
  double root_vertical_offset = 0.0; // metres: the root's per-cycle offset along up
  Vec3 root_advance = Vec3::Zero();  // clip units: the root's per-cycle offset D
  std::size_t joints = 0;            // joints checked (closing + missing)
  double metres_per_unit = 1.0;      // the clip's unit, for root_advance in metres
};

// The cycle check of a clip on a uniform frame grid (clip/frames.h) of at least 3
// frames; `form` forces a form. Errors (one line): no frame rate, fewer than 3 frames.
Result<LoopCheck> check_loop(const Clip& clip, std::optional<LoopForm> form = std::nullopt,
                             const LoopTolerance& tolerance = {});

// A translation track's per-cycle offset D in `form` (see above); `frame` in seconds.
Vec3 per_cycle_offset(const TranslationTrack& track, LoopForm form, double frame);

// "auto" (nothing), "closed", "open"; an error naming the valid words otherwise.
Result<std::optional<LoopForm>> parse_loop_form(std::string_view text);

// "2 joints miss closure (a pop at the seam in the source): L_Arm 4.40°, R_Arm 1.20°", the
// eight largest and "…" after them; "" when none misses.
std::string closure_misses_text(const std::vector<ClosureMiss>& misses);

// One line for a user: "looks like a cycle (closed form: 38 frames, 1.267 s per period); joints
// close within 0.0050°", or "not a cycle (…); 2 joints close within 0.0000°; 1 joint misses
// closure (…): L_Arm 4.40°". Each joint is counted once (closing or missing). The root
// "rises" along up or "translates" along the ground per cycle; "nothing moves" only when
// no joint turns and the root stays, "no joint turns" when only the root moves.
std::string loop_check_text(const LoopCheck& check);

}  // namespace rotinterp
