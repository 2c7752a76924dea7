// The samples of an evaluated clip handled block by block (private to src/eval/): how
// many at a time, and the reference over one block, so that memory stays bounded by
// the clip for any subframe count.
#pragma once

#include "rotinterp/eval/evaluate_clip.h"

#include <cstddef>
#include <vector>

namespace rotinterp::detail {

// Samples are handled in blocks of at least the clip's frame count (all at once
// without subframes) and at least kBlockSampleJoints / joints, about 150 bytes per
// sample and joint (≈ 20 MB): for any subframe count K memory stays proportional
// to the clip, never to K.
inline constexpr std::size_t kBlockSampleJoints = 1 << 17;
std::size_t block_samples(const ClipReference& R);

// The reference over samples [m0, m0 + n). Without subframes its rows are the
// stored frames themselves; otherwise they are computed here.
class Block {
 public:
  // `only`: the one joint whose rotations are needed (no translations, no poses),
  // or kAllJoints.
  static constexpr std::size_t kAllJoints = static_cast<std::size_t>(-1);
  void fill(const ClipReference& R, std::size_t m0, std::size_t n, bool poses, std::size_t only = kAllJoints);
  const std::vector<double>& times() const { return times_; }
  const Quat* rotation(const ClipReference& R, std::size_t j) const {
    return direct_ ? R.reference[j].data() + m0_ : rotation_[j].data();
  }
  const Vec3* translation(const ClipReference& R, std::size_t j) const {
    return direct_ ? R.translation[j].data() + m0_ : translation_[j].data();
  }
  const WorldPose& world(const ClipReference& R, std::size_t m) const {
    const std::size_t s = m0_ + m;
    return s % R.per_frame == 0 ? R.world[s / R.per_frame] : world_[m];
  }

 private:
  std::size_t m0_ = 0;
  bool direct_ = true;
  std::vector<double> times_;
  std::vector<std::vector<Quat>> rotation_;
  std::vector<std::vector<Vec3>> translation_;
  std::vector<WorldPose> world_;
};

}  // namespace rotinterp::detail
