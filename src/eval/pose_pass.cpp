// The rebuilt motion's forward kinematics and pose errors, joint-major over chunks of samples.
#include "pose_pass.h"

#include <algorithm>

namespace rotinterp::detail {

void PosePass::add(const ClipReference& R, const Block& block, std::size_t m0, std::size_t n,
                   const Quat* const* test, PoseError& acc, std::vector<std::vector<Vec3>>& feet_at) {
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size();
  equal_.resize(kPoseChunk);
  ref_.resize(kPoseChunk);
  differ_.resize(kPoseChunk);
  rotation_.resize(nj * kPoseChunk);
  position_.resize(nj * kPoseChunk);
  end_site_.resize(ne * kPoseChunk);
  for (std::size_t c0 = 0; c0 < n; c0 += kPoseChunk) {
    const std::size_t cn = std::min(kPoseChunk, n - c0);
    // Which samples reproduce the reference bit for bit (at keys): their errors are 0.
    // Sample by sample, stopping at the first joint that differs (most do at once).
    for (std::size_t m = 0; m < cn; ++m) {
      bool equal = true;
      for (std::size_t j = 0; j < nj && equal; ++j) equal = test[j][c0 + m].coeffs() == block.rotation(R, j)[c0 + m].coeffs();
      equal_[m] = equal;
    }
    std::size_t nd = 0;
    for (std::size_t m = 0; m < cn; ++m) {
      ref_[m] = &block.world(R, c0 + m);
      if (!equal_[m]) differ_[nd++] = m;
    }
    // Forward kinematics of the differing samples, parents before children (clip/clip.h).
    for (std::size_t j = 0; j < nj; ++j) {
      const int p = skel.joints[j].parent;
      const Quat* local_r = test[j] + c0;
      const Vec3* local_t = block.translation(R, j) + c0;
      Quat* wr = &rotation_[j * kPoseChunk];
      Vec3* wp = &position_[j * kPoseChunk];
      if (p < 0) {
        for (std::size_t i = 0; i < nd; ++i) wr[i] = local_r[differ_[i]], wp[i] = local_t[differ_[i]];
        continue;
      }
      const Quat* pr = &rotation_[static_cast<std::size_t>(p) * kPoseChunk];
      const Vec3* pp = &position_[static_cast<std::size_t>(p) * kPoseChunk];
      for (std::size_t i = 0; i < nd; ++i) {
        wr[i] = pr[i] * local_r[differ_[i]];
        wp[i] = pp[i] + pr[i] * local_t[differ_[i]];
      }
    }
    for (std::size_t e = 0; e < ne; ++e) {
      const EndSite& s = skel.end_sites[e];
      const Quat* pr = &rotation_[s.parent * kPoseChunk];
      const Vec3* pp = &position_[s.parent * kPoseChunk];
      for (std::size_t i = 0; i < nd; ++i) end_site_[e * kPoseChunk + i] = pp[i] + pr[i] * s.offset;
    }
    // The errors, each accumulator in sample order.
    for (std::size_t j = 0; j < nj; ++j) {
      RunningError& pos = acc.joint_position[j];
      RunningError& shell = acc.joint_shell[j];
      const Quat* wr = &rotation_[j * kPoseChunk];
      const Vec3* wp = &position_[j * kPoseChunk];
      for (std::size_t m = 0, i = 0; m < cn; ++m) {
        if (equal_[m]) {
          pos.add(0.0);
          shell.add(0.0);
          continue;
        }
        const WorldPose& ref = *ref_[m];
        pos.add((ref.position[j] - wp[i]).norm());
        shell.add(shell_error(ref.rotation[j], ref.position[j], wr[i], wp[i], R.shell_distance));
        ++i;
      }
    }
    for (std::size_t e = 0; e < ne; ++e) {
      RunningError& pos = acc.end_site_position[e];
      const Vec3* we = &end_site_[e * kPoseChunk];
      for (std::size_t m = 0, i = 0; m < cn; ++m)
        pos.add(equal_[m] ? 0.0 : (ref_[m]->end_site_position[e] - we[i++]).norm());
    }
    // The rebuilt feet at frames.
    for (std::size_t m = 0, i = 0; m < cn; ++m) {
      const std::size_t s = m0 + c0 + m;
      const bool frame = s % R.per_frame == 0;
      if (frame)
        for (std::size_t f = 0; f < R.feet.size(); ++f)
          feet_at[f][s / R.per_frame] = equal_[m] ? ref_[m]->position[R.feet[f]] : position_[R.feet[f] * kPoseChunk + i];
      if (!equal_[m]) ++i;
    }
  }
}

}  // namespace rotinterp::detail
