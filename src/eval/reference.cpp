// The reference side of one evaluated clip, computed once for every method: frames, poses, feet, smoothness.
#include "rotinterp/eval/evaluate_clip.h"

#include "sample_block.h"
#include "streamed_stats.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace rotinterp {

using detail::Block;
using detail::block_samples;
using detail::SmoothnessSum;

namespace {

constexpr double kRadToDeg = 180.0 / kPi;

std::atomic<std::size_t> prepared{0};

}  // namespace

std::size_t references_prepared() { return prepared.load(); }

Result<ClipReference> prepare_reference(const Clip& clip, const std::string& clip_id,
                                        const ClipEvalOptions& options) {
  ++prepared;
  if (Status s = clip.validate(); !s) return s.failure(clip_id + ": ");
  if (options.subframe < 0 || options.subframe > 1000)
    return make_error(clip_id + ": subframe must be between 0 and 1000");
  ClipReference R;
  if (options.loop) {
    auto cycle = cycle_frames(clip, options.loop_form);
    if (!cycle) return cycle.failure(clip_id + ": ");
    R.cycle = std::move(*cycle);
  }
  R.clip_id = clip_id;
  R.skeleton = clip.skeleton;
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size();

  // ---- the sample grid: the clip's frames (clip/frames.h), and subframes between them ----
  DenseClip dense = dense_clip(clip);
  R.frames = std::move(dense.grid.times);
  const std::size_t nf = R.frames.size();
  const std::size_t per = R.per_frame = static_cast<std::size_t>(options.subframe) + 1;
  R.samples = nf == 0 ? 0 : (nf - 1) * per + 1;
  R.sample_dt = clip.frame_time > 0.0 ? clip.frame_time / static_cast<double>(per) : 0.0;

  // ---- the original at its frames (keys come from here), the reference at every frame ----
  R.original = std::move(dense.rotation);
  R.translation = std::move(dense.translation);
  if (options.truth) {
    R.reference.assign(nj, std::vector<Quat>(nf));
    std::vector<Quat> r(nj);
    std::vector<Vec3> t(nj);
    for (std::size_t k = 0; k < nf; ++k) {
      options.truth(R.frames[k], r, t);
      if (r.size() != nj || t.size() != nj) return make_error(clip_id + ": the analytic truth has another skeleton");
      for (std::size_t j = 0; j < nj; ++j) {
        R.reference[j][k] = normalized_or_identity(r[j]);
        R.translation[j][k] = t[j].allFinite() ? t[j] : skel.joints[j].offset;
      }
    }
    R.truth = options.truth;
  } else {
    R.reference = R.original;
    if (per > 1) R.translation_tracks = clip.translations;
  }

  // ---- reference world poses at the frames, computed once (when a metric needs them) ----
  R.metrics = options.metrics;
  const bool poses = options.metrics.needs_poses();
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  auto world_at = [&](std::size_t k, WorldPose& out) {
    for (std::size_t j = 0; j < nj; ++j) {
      local_r[j] = R.reference[j][k];
      local_t[j] = R.translation[j][k];
    }
    forward_kinematics(skel, local_r, local_t, out);
  };
  R.world.resize(poses ? nf : 0);
  for (std::size_t k = 0; k < R.world.size(); ++k) world_at(k, R.world[k]);

  R.height = skeleton_height(rest_pose(skel));
  if (!(R.height > 0.0) && nf > 0) {
    WorldPose first;
    world_at(0, first);
    R.height = skeleton_height(first);
  }
  if (!(R.height > 0.0)) R.height = 1.0;
  R.shell_distance = in_clip_units(clip, options.shell_distance_m);
  R.bone_axis = bone_axes(skel);

  // ---- the source's keys and range of motion, per joint ----
  R.keys.assign(nj, 0.0);
  R.motion_deg.assign(nj, 0.0);
  for (std::size_t j = 0; j < nj; ++j) {
    R.keys[j] = static_cast<double>(clip.rotations[j].keys.size());
    for (std::size_t k = 1; k < nf; ++k)
      R.motion_deg[j] = std::max(R.motion_deg[j], angular_distance(R.original[j][0], R.original[j][k]) * kRadToDeg);
  }

  // ---- foot contact of the reference, at its frames ----
  R.metres_per_unit = clip.unit.metres_per_unit;
  R.unit = describe_unit(clip.unit);
  if (options.metrics.has(Metric::foot_skating)) {  // else no feet, no foot rows
    auto feet = options.feet.feet.empty() ? Result<std::vector<std::size_t>>(find_feet(skel))
                                          : feet_by_name(skel, options.feet.feet);
    if (!feet) return feet.failure(clip_id + ": ");
    R.feet = std::move(*feet);
  }
  if (options.feet.floor_m) {
    R.floor = *options.feet.floor_m / R.metres_per_unit;
  } else if (!R.feet.empty() && nf > 0) {
    R.floor = INFINITY;
    for (std::size_t f : R.feet)
      for (std::size_t k = 0; k < nf; ++k) R.floor = std::min(R.floor, R.world[k].position[f].y());
  }
  {
    std::vector<Vec3> at(nf);
    for (std::size_t f : R.feet) {
      for (std::size_t k = 0; k < nf; ++k) at[k] = R.world[k].position[f];
      R.foot_ref.push_back(foot_contact(at.data(), R.frames.data(), nf, R.floor, R.metres_per_unit, options.feet));
    }
  }
  R.reference_acc_rms.assign(nj, 0.0);
  if (!options.metrics.has(Metric::smoothness)) return R;
  if (per == 1) {
    for (std::size_t j = 0; j < nj; ++j)
      R.reference_acc_rms[j] = sampled_smoothness(R.reference[j].data(), nf, R.sample_dt).acceleration_rms;
    return R;
  }
  // Subframes: the reference's smoothness block by block.
  std::vector<SmoothnessSum> smooth(nj);
  std::vector<std::vector<Quat>> carried(nj);
  Block block;
  std::vector<Quat> q;
  for (std::size_t m0 = 0; m0 < R.samples; m0 += block_samples(R)) {
    const std::size_t n = std::min(block_samples(R), R.samples - m0);
    block.fill(R, m0, n, false);
    for (std::size_t j = 0; j < nj; ++j) {
      q = carried[j];
      q.insert(q.end(), block.rotation(R, j), block.rotation(R, j) + n);
      smooth[j].add(q.data(), q.size(), R.sample_dt);
      carried[j].assign(q.end() - static_cast<std::ptrdiff_t>(std::min<std::size_t>(2, q.size())), q.end());
    }
  }
  for (std::size_t j = 0; j < nj; ++j) R.reference_acc_rms[j] = smooth[j].rms();
  return R;
}

}  // namespace rotinterp
