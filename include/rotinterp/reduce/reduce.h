// Key reduction: the fewest keys per joint from which a clip, rebuilt with a given
// interpolator, stays within an error budget at EVERY source frame.
//
// The source is the clip's motion at its frames (clip/frames.h: dense_clip). For
// each joint the kept keys are a subset of those frames, always including the first
// and the last; the rebuilt clip is each joint's rotation through its kept keys with
// the method (interp/interpolator.h) and each translation track through its kept
// keys with the translation curve (clip/translation_curve.h).
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
//    one (> 0).
//
// The selection (per joint, parents before children):
//  1. insertion: from the first and last frame, insert into every key interval
//     whose worst frame is over budget that worst frame; repeat until no frame is;
//  2. removal: try removing each interior key in turn, keep it removed if every
//     frame between its second neighbours on either side stays within budget (the
//     curve rebuilt from the nearby keys);
//  3. verification at every frame with the whole track; where a global method
//     (c2, bf, expmap-c2) moved beyond the checked window, back to 1 (insertion
//     only).
// With a shell budget, each joint also holds its children's positions within 90 %
// of their budget (leaving them room for their own keys), and a frame that a joint
// cannot meet even keyed itself (its ancestors' rebuilt motion already puts its vertices beyond the budget) becomes a
// key of its own translation track, else of the nearest ancestors not yet keyed
// there — as many of them, nearest first, as it takes to meet the budget at that
// frame; their subtrees are then verified again (insertion only). Keys only
// grow in these repairs, so the loop ends; a frame keyed on a joint and all its
// ancestors is reproduced exactly (to the methods' 1e-9 rad at keys).
// The result is near-minimal, not minimal (finding the minimum is a search over
// subsets for the non-local methods).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

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
};

struct ReducedJoint {
  std::vector<std::size_t> rotation_frames;     // kept frames (indices of the grid), sorted
  std::vector<std::size_t> translation_frames;  // the same for its translation track; empty without one
  ReduceBudget budget;                          // the budget applied
  // The largest errors over every frame of the final rebuilt clip.
  double max_rotation_error = 0.0;     // rad
  double max_shell_error = 0.0;        // clip units (0 without a shell budget)
  double max_translation_error = 0.0;  // clip units
};

struct ReduceResult {
  FrameGrid grid;   // the source's frames
  Clip reduced;     // the source clip with each track holding only its kept keys
  std::vector<ReducedJoint> joints;
  std::size_t source_keys = 0;  // frames × (joints + translation tracks)
  std::size_t kept_keys = 0;    // rotation + translation keys kept
};

// Errors: an invalid clip, an unknown method or joint name, a budget that is not a
// finite number ≥ 0, no budget at all for a joint, a translation track without a
// translation budget, a shell budget without a shell distance.
Result<ReduceResult> reduce_clip(const Clip& clip, const ReduceOptions& options);

// Rebuilds a joint's rotation at the frames `times` from its kept frames (the same
// construction the selection checks): decimated_track + the method. Used by callers
// that measure a reduction themselves.
Result<std::vector<Quat>> rebuild_rotations(const std::string& method, const std::vector<double>& times,
                                            const std::vector<Quat>& source, const std::vector<std::size_t>& kept);

}  // namespace rotinterp
