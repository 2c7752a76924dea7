// The sample grid of an evaluated clip (frames and subframes) and the reference over a block of it.
#include "sample_block.h"

#include "rotinterp/interp/slerp.h"

#include <algorithm>

namespace rotinterp {

namespace {

// Subframe times fall between frames by design: only round-off may take a key there.
constexpr double kSubframeSnap = 1e-9;

}  // namespace

double sample_time(const ClipReference& R, std::size_t m) {
  const std::size_t per = R.per_frame, k = m / per, i = m % per;
  return i == 0 ? R.frames[k]
                : R.frames[k] + (R.frames[k + 1] - R.frames[k]) * static_cast<double>(i) / static_cast<double>(per);
}

namespace detail {

std::size_t block_samples(const ClipReference& R) {
  return std::max({R.frames.size(), kBlockSampleJoints / std::max<std::size_t>(R.skeleton.joints.size(), 1),
                   std::size_t{64}});
}

void Block::fill(const ClipReference& R, std::size_t m0, std::size_t n, bool poses, std::size_t only) {
  m0_ = m0;
  direct_ = R.per_frame == 1;
  const std::size_t nj = R.skeleton.joints.size();
  times_.resize(n);
  for (std::size_t m = 0; m < n; ++m) times_[m] = sample_time(R, m0 + m);
  world_.clear();
  if (direct_) return;
  rotation_.resize(nj);
  translation_.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) rotation_[j].resize(n), translation_[j].resize(n);
  std::vector<Quat> r(nj);
  std::vector<Vec3> t(nj);
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t k = (m0 + m) / R.per_frame, i = (m0 + m) % R.per_frame;
    if (i == 0 || R.truth) {
      if (i != 0) R.truth(times_[m], r, t);
      for (std::size_t j = 0; j < nj; ++j) {
        rotation_[j][m] = i == 0 ? R.reference[j][k] : normalized_or_identity(r[j]);
        translation_[j][m] = i == 0 ? R.translation[j][k] : t[j].allFinite() ? t[j] : R.skeleton.joints[j].offset;
      }
      continue;
    }
    const double u = static_cast<double>(i) / static_cast<double>(R.per_frame);
    for (std::size_t j = only == kAllJoints ? 0 : only; j < (only == kAllJoints ? nj : only + 1); ++j)
      rotation_[j][m] = slerp(R.original[j][k], R.original[j][k + 1], u);
  }
  if (only != kAllJoints) return;
  if (!R.truth)
    for (std::size_t j = 0; j < nj; ++j) {
      if (R.translation_tracks[j])
        sample_translations(*R.translation_tracks[j], times_, kSubframeSnap * R.sample_dt, translation_[j].data());
      else
        std::fill(translation_[j].begin(), translation_[j].end(), R.skeleton.joints[j].offset);
    }
  if (!poses) return;
  world_.resize(n);
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  for (std::size_t m = 0; m < n; ++m) {
    if ((m0 + m) % R.per_frame == 0) continue;  // a frame: stored
    for (std::size_t j = 0; j < nj; ++j) local_r[j] = rotation_[j][m], local_t[j] = translation_[j][m];
    forward_kinematics(R.skeleton, local_r, local_t, world_[m]);
  }
}

}  // namespace detail

}  // namespace rotinterp
