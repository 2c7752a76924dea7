// An FBX file's motion as our reader replays it, measured against the source at
// every frame (private to src/io; io/fbx/fbx_reduced.h uses it to check what it writes).
#pragma once

#include "rotinterp/clip/frames.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_reduced.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rotinterp {

// Per joint and frame: [joint][frame].
struct FbxReplayErrors {
  std::vector<std::vector<double>> rotation_deg;  // local rotation angle
  // Virtual vertices in object space, and the joint's children's positions (0
  // without a shell budget).
  std::vector<std::vector<double>> shell;
  std::vector<std::vector<double>> translation;   // local translation (0 for joints without a track)
};

// `bytes` parsed, read (io/fbx/fbx_curves.h) and evaluated (io/fbx/fbx_transform.h) in its
// first take at `frame_ticks` (one per source frame), each joint's node found by
// name, against `source` (whose skeleton is `skeleton`), its translations mapped
// back through each joint's frame (one per joint). Shell errors only for
// joints whose budget has one. Errors: the file does not parse, has no take, or
// lacks a joint's node.
Result<FbxReplayErrors> fbx_replay_errors(const std::string& bytes, const Skeleton& skeleton, const DenseClip& source,
                                          const std::vector<std::int64_t>& frame_ticks,
                                          const std::vector<FbxJointBudget>& budgets, double shell_distance,
                                          const std::vector<FbxJointFrame>& joint_frames);

}  // namespace rotinterp
