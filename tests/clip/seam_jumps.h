// Velocity jumps of a sampled cycle, frame to frame: the seam's against the largest inside.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/loop.h"

#include <algorithm>
#include <vector>

namespace rotinterp::test {

struct SeamJump {
  double seam = 0.0;    // rad/s: |ω₀ − ωₘ₋₁|, across the end-to-start seam
  double inside = 0.0;  // rad/s: the largest |ωₖ − ωₖ₋₁| between other frames
};

// ωₖ = log(qₖ₊₁qₖ⁻¹)/Δ over one period of a uniformly sampled track; in the closed
// form the last key is the seam's end, in the open form the first key follows the last.
inline SeamJump seam_jump(const RotationTrack& r, LoopForm form, double frame_time) {
  std::vector<Quat> q = r.keys;
  if (form == LoopForm::open) q.push_back(q.front());
  std::vector<Vec3> w;
  for (std::size_t k = 0; k + 1 < q.size(); ++k) w.push_back(displacement_fixed(q[k], q[k + 1]).vec() / frame_time);
  SeamJump j;
  if (w.size() < 2) return j;
  j.seam = (w.front() - w.back()).norm();
  for (std::size_t k = 1; k < w.size(); ++k) j.inside = std::max(j.inside, (w[k] - w[k - 1]).norm());
  return j;
}

}  // namespace rotinterp::test
