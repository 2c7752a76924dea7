// A reduced clip (reduce/reduce.h) as sparse FBX curves that replay its method's
// curve: what `rotinterp reduce -o OUT.fbx` writes.
//
// FBX stores each joint's rotation as three Euler curves (degrees, in the joint's
// rotation order), not as the quaternion curve a method builds, so the file is
// written, read back through our own reader (io/fbx/fbx_curves.h) and evaluated as the
// DCC does (io/fbx/fbx_curve_eval.h, fbx_transform.h) at every source frame, and keys
// are added until that replay stays within the budget reduce applied:
//  * keys: each kept key of the reduced clip, its Euler angles the method's curve
//    there, unwrapped frame by frame along the curve (euler_nearest: no 360° jumps,
//    continuous through gimbal lock); slerp and nlerp as linear keys, every other
//    method as cubic keys with user tangents — the one-sided slopes of the method's
//    curve in Euler angles on either side (broken where they differ);
//  * translations: the reduced translation track through its translation curve
//    (linear keys, or cubic keys with its Hermite tangents, which FBX replays
//    exactly);
//  * check: per joint and frame, the same budgets as reduce (local rotation angle;
//    shell — virtual vertices at shell_distance in object space and the joint's
//    children's positions, every ancestor replayed from the file too; local
//    translation); in every key interval over
//    budget its worst frame becomes a key on the method's curve (slopes from both
//    sides of it); a key frame still over budget takes the source's value, then
//    its ancestors' keys there do, nearest first. The loop ends when every frame is
//    within budget or no key is left to add or correct.
// Rotation keys share their times over the three axes (one key time counts once,
// as reduce counts a key).
// From an FBX character (options.character): the curves are in its models' own
// conventions (io/fbx/fbx_character.h FbxJointFrame), keyed on its source take's
// time axis, and the file checked is the character's tree with them as its one take.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_character.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// One joint's budget as reduce applied it (reduce/reduce.h ReducedJoint::budget);
// 0: not bounded.
struct FbxJointBudget {
  double rotation_deg = 0.0;  // local rotation angle, degrees
  double shell = 0.0;         // virtual-vertex distance in object space, clip units
  double translation = 0.0;   // local translation, clip units
};

struct FbxReducedOptions {
  std::string method = "slerp";  // the method the keys were chosen for (interp/interpolator.h)
  TranslationInterp translation = TranslationInterp::cubic;
  std::vector<FbxJointBudget> budgets;  // one per joint
  double shell_distance = 0.0;          // clip units; > 0 where a shell budget is set
  bool ascii = false;                   // ASCII FBX 7.4 (default binary; a character's ASCII source: ASCII)
  // The FBX character the source clip was read from, or null: the skeleton alone.
  const FbxCharacter* character = nullptr;
};

struct FbxReducedResult {
  std::string bytes;  // the FBX file
  std::size_t rotation_keys = 0, translation_keys = 0;  // key times written, over all joints
  std::size_t added_keys = 0;    // of those, beyond the reduced clip's
  std::size_t corrected_keys = 0;  // keys given the source's value
  // The largest errors of the file as our reader replays it, over every frame.
  double max_rotation_error_deg = 0.0;
  double max_shell_error = 0.0;        // clip units (0 without a shell budget)
  double max_translation_error = 0.0;  // clip units
  bool within_budget = true;           // every frame of every joint within its budget
  std::optional<FbxKept> kept;         // what passed through, from a character
};

// `reduced` holds the kept keys (ReduceResult::reduced), `source` is the clip they
// were chosen from; both valid, with the same skeleton, every reduced key on a
// source frame. Errors: those, an unknown method, budgets not one per joint.
Result<FbxReducedResult> encode_reduced_fbx(const Clip& reduced, const Clip& source, const FbxReducedOptions& options);

}  // namespace rotinterp
