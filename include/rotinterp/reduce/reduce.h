// Key reduction: the fewest keys per joint from which a clip, rebuilt with a given
// interpolator, stays within an error budget at EVERY source frame.
//
// The source is the clip's motion at its frames (clip/frames.h: dense_clip). For
// each joint the kept keys lie at a subset of those frames, always including the
// first and the last (in a cycle: below); the rebuilt clip is each joint's rotation through its kept
// keys with the method (interp/interpolator.h) and each translation track through
// its kept keys with the translation curve (clip/translation_curve.h). Translation
// keys hold the source's values; rotation keys may hold FITTED values (below), so
// the keys are those of `ReduceResult::reduced`, not the source at the kept frames.
//
// Budgets (each joint's may be overridden; a budget of 0 is not applied):
//  * rotation_deg — the joint's local rotation error: the geodesic angle between the
//    source and the rebuilt local rotation (angular_distance), degrees.
//  * shell — ACL's virtual-vertex error, clip units: points at `shell_distance`
//    along the joint's local x, y and z axes, carried to object space by the joint's
//    world transform; the largest displacement between the source and the rebuilt
//    pose, where the rebuilt pose uses every ANCESTOR's rebuilt motion too (rotations
//    and translations), so that errors cannot pile up down a chain.
//  * translation — the local translation error of a joint's translation track
//    (|source − rebuilt|, clip units). Every joint with a translation track needs
//    one (> 0). With a shell budget the track is held to half of that too (its
//    error moves the joint's whole subtree): translation_tolerance.
//
// The selection (per joint, parents before children):
//  1. insertion: from the first and last frame, insert into every key interval
//     whose worst frame is over budget that worst frame, with the source's value;
//     repeat until no frame is;
//  2. removal: try removing each interior key in turn, keep it removed if every
//     frame between its second neighbours on either side stays within budget (the
//     curve rebuilt from the nearby keys); if not, and if that is at most 1.25 times
//     the budget, refit the values of its two neighbouring keys (Gauss–Newton on the
//     budget's own residuals: angle vector, shell vertices, children's positions,
//     reweighted towards the largest) and keep it removed if that brings every
//     frame between its third neighbours within budget;
//  3. verification at every frame with the whole track; where a global method
//     (c2, bf, expmap-c2) moved beyond the checked window, back to 1 (insertion
//     only; a key frame over budget gets the source's value back).
// With a shell budget, each joint also holds its children's positions within 90 %
// of their budget (leaving them room for their own keys), and a frame that a joint
// cannot meet even keyed itself (its ancestors' rebuilt motion already puts its
// vertices beyond the budget) becomes a key, with the source's value, of the tracks
// that lower its error there — its own translation, its ancestors' rotations and
// translations, nearest first — as many as it takes; their subtrees are then
// verified again (insertion only). Keys only grow in these repairs and fitted values
// only return to the source's, so the loop ends; a frame keyed with the source's
// values on a joint and all its ancestors is reproduced exactly (to the methods'
// 1e-9 rad at keys).
// A cycle (options.loop; clip/loop.h): each joint that closes is rebuilt on its
// periodic curve (interp/periodic.h; translations with their per-cycle offset,
// clip/translation_curve.h) and measured on it at every frame; its first frame is the
// seam, its one forced key (its value fitted), and the last frame no key of its own; the
// last key interval runs round the seam, and removals and refits are checked on the
// whole periodic curve. In a closed cycle the last frame is the first again: the looped
// joints are measured there against the first frame's rotations. Joints that miss
// closure keep their ends. The reduced clip closes every looped track with a key one
// period after the first (the first key again; translations moved by the offset), not
// counted as kept, so that resample --loop and a reader unaware of cycles replay it.
// The result is near-minimal, not minimal (finding the minimum is a search over
// subsets and values for the non-local methods).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

// The defaults of `rotinterp reduce` and rotinterp.reduce when no budget is given:
// ozz-animation's hierarchical tolerance, 1 mm at 10 cm.
inline constexpr double kDefaultReduceToleranceMm = 1.0;      // millimetres
inline constexpr double kDefaultReduceShellDistanceCm = 10.0;  // centimetres

// A budget as users write it (reduce --tolerance, rotinterp.reduce(tolerance=)):
// items each with its unit, an angle (0.5deg, 0.01rad) on each joint's local rotation
// and/or a length (1mm, 0.1cm) on the shell and translation error. A bare number is
// refused, since the list takes both kinds.
struct BudgetText {
  double deg = 0.0, mm = 0.0;  // 0 = not given
};
// Adds the items of one comma list to `b`; errors start with `what`.
Status add_budget_items(const std::string& what, const std::string& list, BudgetText& b);

struct ReduceBudget {
  double rotation_deg = 0.0;  // local rotation error, degrees; 0 = not bounded
  double shell = 0.0;         // virtual-vertex error in object space, clip units; 0 = not bounded
  double translation = 0.0;   // local translation error of a translation track, clip units
};

struct ReduceOptions {
  std::string method = "slerp";  // any name of methods()
  TranslationInterp translation = TranslationInterp::cubic;
  ReduceBudget budget;  // every joint's, unless overridden
  // Per-joint overrides by joint name: each field > 0 replaces the default's.
  std::vector<std::pair<std::string, ReduceBudget>> budget_for;
  double shell_distance = 0.0;  // clip units; > 0 where a shell budget is set
  unsigned threads = 0;         // without a shell budget joints are independent: 0 = one per core
  ProgressFn progress;          // (joints done, joints)
  // The clip is one period of a cycle (reduce --loop; clip/loop.h): off by default;
  // `loop_form` forces the form, else it is detected.
  bool loop = false;
  std::optional<LoopForm> loop_form;
};

struct ReducedJoint {
  std::vector<std::size_t> rotation_frames;     // kept frames (indices of the grid), sorted
  std::vector<std::size_t> translation_frames;  // the same for its translation track; empty without one
  ReduceBudget budget;                          // the budget applied (translation: translation_tolerance)
  // The largest errors over every frame of the final rebuilt clip.
  double max_rotation_error = 0.0;     // rad
  double max_shell_error = 0.0;        // clip units (0 without a shell budget)
  double max_translation_error = 0.0;  // clip units
  // In a cycle: on its periodic curve, its last key (rotation and translation) the
  // closing one — the first again one period on — not counted as kept.
  bool looped = false;
};

struct ReduceResult {
  FrameGrid grid;   // the source's frames
  Clip reduced;     // the source clip with each track holding only its kept keys
  std::vector<ReducedJoint> joints;
  std::size_t source_keys = 0;  // frames × (joints + translation tracks)
  std::size_t kept_keys = 0;    // rotation + translation keys kept
  std::optional<LoopCheck> cycle;  // the cycle's check, with loop
};

// The translation error a joint's translation track is held to: its translation
// budget, and with a shell budget at most half of that — a joint's translation error
// moves its own vertices and its whole subtree, and left the whole shell budget a
// root's would leave its descendants none.
double translation_tolerance(const ReduceBudget& budget);

// Errors: an invalid clip, an unknown method or joint name, a budget that is not a
// finite number ≥ 0, no budget at all for a joint, a translation track without a
// translation budget, a shell budget without a shell distance.
Result<ReduceResult> reduce_clip(const Clip& clip, const ReduceOptions& options);

}  // namespace rotinterp
