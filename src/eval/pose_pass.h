// The rebuilt motion's world poses and their position and shell errors against
// the reference (private to src/eval/): forward kinematics joint-major over chunks
// of samples, straight from the per-joint sample arrays evaluate_method fills.
#pragma once

#include "sample_block.h"

#include <cstddef>
#include <vector>

namespace rotinterp::detail {

// Samples per chunk: a chunk's joint-major poses stay in cache (64 samples × 56
// bytes per joint).
inline constexpr std::size_t kPoseChunk = 64;

// One per evaluate_method call: its buffers are sized once and reused for every
// block and spacing, so a sample costs no allocation.
class PosePass {
 public:
  // The block of n samples from m0 (`block`, filled with poses): test[j] points at
  // joint j's rebuilt rotations over it. Adds each sample to `acc` — per joint and
  // End Site in sample order, the numbers accumulate_pose_error (or, where every
  // joint equals the reference bit for bit, accumulate_equal_poses) adds — and at
  // frame samples writes the rebuilt feet into feet_at[foot][frame].
  void add(const ClipReference& R, const Block& block, std::size_t m0, std::size_t n, const Quat* const* test,
           PoseError& acc, std::vector<std::vector<Vec3>>& feet_at);

 private:
  std::vector<unsigned char> equal_;    // [sample in chunk]: every joint as the reference's
  std::vector<std::size_t> differ_;     // the chunk's samples that are not
  std::vector<const WorldPose*> ref_;   // [sample in chunk]: the reference pose
  std::vector<Quat> rotation_;          // [joint · kPoseChunk + i]: world rotation of differ_[i]
  std::vector<Vec3> position_;          // likewise, world position
  std::vector<Vec3> end_site_;          // [end site · kPoseChunk + i]
};

}  // namespace rotinterp::detail
