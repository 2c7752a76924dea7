#include "rotinterp/eval/evaluate_clip.h"

#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/slerp.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <utility>

namespace rotinterp {

namespace {

constexpr double kRadToDeg = 180.0 / kPi;

// Subframe times fall between frames by design: only round-off may take a key there.
constexpr double kSubframeSnap = 1e-9;

}  // namespace

std::vector<int> skipped_spacings(std::size_t frames, const ClipEvalOptions& options) {
  std::vector<int> out;
  for (int n : options.keep_every)
    if (frames < options.min_frames || frames < 2 * static_cast<std::size_t>(std::max(n, 1)) + 1) out.push_back(n);
  return out;
}

double sample_time(const ClipReference& R, std::size_t m) {
  const std::size_t per = R.per_frame, k = m / per, i = m % per;
  return i == 0 ? R.frames[k]
                : R.frames[k] + (R.frames[k + 1] - R.frames[k]) * static_cast<double>(i) / static_cast<double>(per);
}

namespace {

// Samples are handled in blocks of at least the clip's frame count (all at once
// without subframes) and at least kBlockSampleJoints / joints, about 150 bytes per
// sample and joint (≈ 20 MB): for any subframe count K memory stays proportional
// to the clip, never to K.
constexpr std::size_t kBlockSampleJoints = 1 << 17;
std::size_t block_samples(const ClipReference& R) {
  return std::max({R.frames.size(), kBlockSampleJoints / std::max<std::size_t>(R.skeleton.joints.size(), 1),
                   std::size_t{64}});
}

// The reference over samples [m0, m0 + n). Without subframes its rows are the
// stored frames themselves; otherwise they are computed here.
class Block {
 public:
  // `only`: the one joint whose rotations are needed (no translations, no poses),
  // or kAllJoints.
  static constexpr std::size_t kAllJoints = static_cast<std::size_t>(-1);
  void fill(const ClipReference& R, std::size_t m0, std::size_t n, bool poses, std::size_t only = kAllJoints) {
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

// sampled_smoothness over a stream of blocks: each block's samples follow the
// two before it (kept in front of the next block), so every second difference is
// counted once. One block gives exactly sampled_smoothness of all samples.
struct SmoothnessSum {
  double sum_sq = 0.0, max = 0.0, first_rms = 0.0;
  std::size_t count = 0, blocks = 0;
  // q[0..n): the two carried samples first unless this is the first block.
  void add(const Quat* q, std::size_t n, double dt) {
    const Smoothness s = sampled_smoothness(q, n, dt);
    const std::size_t c = n >= 3 ? n - 2 : 0;
    sum_sq += s.acceleration_rms * s.acceleration_rms * static_cast<double>(c);
    max = std::max(max, s.acceleration_max);
    count += c;
    if (blocks++ == 0) first_rms = s.acceleration_rms;
  }
  double rms() const {
    if (blocks == 1) return first_rms;  // bit for bit what one call gives
    return count ? std::sqrt(sum_sq / static_cast<double>(count)) : 0.0;
  }
};

// The two order statistics of rank lo and lo + 1 (0-based) of the non-negative
// values `each_block` yields (it calls its argument with (values, n) per block, in
// any order, the same values on every call), with memory independent of their
// count: a radix selection on the values' bit patterns, which non-negative
// doubles order like the numbers; 16 bits per pass, then one pass collects the
// few values left with that prefix and the smallest value above them.
template <class EachBlock>
std::pair<double, double> select_two(const EachBlock& each_block, std::uint64_t lo) {
  constexpr std::size_t kCollect = 1 << 20;
  auto bits = [](double v) {
    std::uint64_t b = 0;
    v = std::isfinite(v) && v > 0.0 ? v : 0.0;  // as percentile() reads them
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::uint64_t prefix = 0, rank = lo, in_bucket = 0;
  int known = 0;  // leading bits fixed so far
  std::vector<std::uint64_t> count(1 << 16);
  while (known < 64) {
    std::fill(count.begin(), count.end(), 0);
    const int shift = 64 - known - 16;
    each_block([&](const double* v, std::size_t n) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t b = bits(v[i]);
        if (known == 0 || (b >> (64 - known)) == prefix) ++count[(b >> shift) & 0xFFFF];
      }
    });
    std::size_t d = 0;
    while (rank >= count[d]) rank -= count[d++];
    prefix = (prefix << 16) | d;
    known += 16;
    in_bucket = count[d];
    if (in_bucket <= kCollect) break;
  }
  std::vector<double> bucket;
  double above = INFINITY;
  each_block([&](const double* v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t b = bits(v[i]), top = b >> (64 - known);
      if (top == prefix && in_bucket <= kCollect) bucket.push_back(std::isfinite(v[i]) && v[i] > 0.0 ? v[i] : 0.0);
      else if (top > prefix) above = std::min(above, v[i]);
    }
  });
  if (in_bucket > kCollect) {  // all 64 bits fixed: every value in the bucket is the same
    double same = 0.0;
    std::memcpy(&same, &prefix, sizeof same);
    return {same, rank + 1 < in_bucket ? same : above};
  }
  std::nth_element(bucket.begin(), bucket.begin() + static_cast<std::ptrdiff_t>(rank), bucket.end());
  const double a = bucket[rank];
  const double b = rank + 1 < bucket.size()
                       ? *std::min_element(bucket.begin() + static_cast<std::ptrdiff_t>(rank) + 1, bucket.end())
                       : above;
  return {a, b};
}

}  // namespace

Result<ClipReference> prepare_reference(const Clip& clip, const std::string& clip_id,
                                        const ClipEvalOptions& options) {
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

  // ---- reference world poses at the frames, computed once ----
  R.world.resize(nf);
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  for (std::size_t k = 0; k < nf; ++k) {
    for (std::size_t j = 0; j < nj; ++j) {
      local_r[j] = R.reference[j][k];
      local_t[j] = R.translation[j][k];
    }
    forward_kinematics(skel, local_r, local_t, R.world[k]);
  }

  R.height = skeleton_height(rest_pose(skel));
  if (!(R.height > 0.0) && nf > 0) R.height = skeleton_height(R.world[0]);
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
  if (options.feet.feet.empty()) {
    R.feet = find_feet(skel);
  } else {
    auto feet = feet_by_name(skel, options.feet.feet);
    if (!feet) return feet.failure(clip_id + ": ");
    R.feet = std::move(*feet);
  }
  R.metres_per_unit = clip.unit.metres_per_unit;
  R.unit = describe_unit(clip.unit);
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

Result<std::vector<ErrorRow>> evaluate_method(const ClipReference& R, const std::string& method,
                                              const ClipEvalOptions& options) {
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size();
  const std::size_t nf = R.frames.size(), ns = R.samples;
  const double pct = 100.0 / R.height;
  const double mpu = R.metres_per_unit;  // the rows are in metres
  for (int n : options.keep_every)
    if (n < 1) return make_error(R.clip_id + ": keep_every must be at least 1");

  const std::size_t bs = block_samples(R);
  const bool one_block = ns <= bs;
  std::vector<ErrorRow> rows;
  rows.reserve(options.keep_every.size() * (nj + ne));
  // test[j]: two samples carried from the previous block (for smoothness), then the block.
  std::vector<std::vector<Quat>> test(nj, std::vector<Quat>(2 + std::min(ns, bs)));
  std::vector<double> scratch;
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  WorldPose test_world;
  Block block;
  const std::vector<int> skipped = skipped_spacings(nf, options);
  const std::size_t nfeet = R.feet.size();
  std::vector<std::vector<Vec3>> feet_at(nfeet, std::vector<Vec3>(nf));  // [foot][frame], rebuilt
  for (int keep : options.keep_every) {
    if (std::find(skipped.begin(), skipped.end(), keep) != skipped.end()) continue;
    const std::vector<std::size_t> kf = keep_every_indices(nf, static_cast<std::size_t>(keep));
    std::vector<RebuiltJoint> rebuilt(nj);  // eval/seam.h: periodic curves with --loop
    std::vector<const Interpolator*> curves(nj);
    for (std::size_t j = 0; j < nj; ++j) {
      auto joint = rebuild_joint(R, j, method, keep);
      if (!joint)
        return joint.failure(R.clip_id + ": joint '" + skel.joints[j].name + "', method " + method + ": ");
      rebuilt[j] = std::move(*joint);
      curves[j] = rebuilt[j].curve.get();
    }
    std::vector<std::vector<Quat>> at_keys(nj, std::vector<Quat>(kf.size()));
    std::vector<SmoothnessSum> smooth(nj);
    std::vector<RotationError> err(nj);  // summed over blocks: angle sums in mean·count, rms²·count
    PoseError pose = make_pose_error(skel);
    for (std::size_t m0 = 0; m0 < ns; m0 += bs) {
      const std::size_t n = std::min(bs, ns - m0);
      block.fill(R, m0, n, true);
      const std::size_t carry = m0 == 0 ? 0 : 2;
      for (std::size_t j = 0; j < nj; ++j) {
        Quat* out = test[j].data() + 2;
        curves[j]->evaluate(block.times().data(), n, out);
        // The curve at its keys is among the samples (frame kf[i] is sample kf[i]·per_frame).
        for (std::size_t i = 0; i < kf.size(); ++i)
          if (const std::size_t s = kf[i] * R.per_frame; s >= m0 && s < m0 + n) at_keys[j][i] = out[s - m0];
        smooth[j].add(out - carry, n + carry, R.sample_dt);
        const RotationError e = rotation_error(block.rotation(R, j), out, n, R.bone_axis[j], scratch);
        if (one_block) {
          err[j] = e;
        } else {
          ErrorStats& a = err[j].angle;
          const double c = static_cast<double>(e.angle.count);
          a.mean += e.angle.mean * c;  // sums until the end
          a.rms += e.angle.rms * e.angle.rms * c;
          a.max = std::max(a.max, e.angle.max);
          a.count += e.angle.count;
          for (auto [sum, part] : {std::pair{&err[j].swing, &e.swing}, {&err[j].twist, &e.twist}}) {
            sum->count += part->count;
            sum->sum += part->sum;
            sum->sum_sq += part->sum_sq;
            sum->max = std::max(sum->max, part->max);
          }
        }
        test[j][0] = n >= 2 ? out[n - 2] : test[j][1];
        test[j][1] = out[n - 1];
      }
      for (std::size_t m = 0; m < n; ++m) {
        bool equal = true;  // the rebuilt pose is the reference's, bit for bit (at keys)
        for (std::size_t j = 0; j < nj; ++j) {
          local_r[j] = test[j][2 + m];
          local_t[j] = block.translation(R, j)[m];
          equal = equal && local_r[j].coeffs() == block.rotation(R, j)[m].coeffs();
        }
        const bool frame = (m0 + m) % R.per_frame == 0;
        if (equal) {
          accumulate_equal_poses(pose);
          if (frame)
            for (std::size_t f = 0; f < nfeet; ++f) feet_at[f][(m0 + m) / R.per_frame] = block.world(R, m).position[R.feet[f]];
          continue;
        }
        forward_kinematics(skel, local_r, local_t, test_world);
        accumulate_pose_error(block.world(R, m), test_world, R.shell_distance, pose);
        if (frame)
          for (std::size_t f = 0; f < nfeet; ++f) feet_at[f][(m0 + m) / R.per_frame] = test_world.position[R.feet[f]];
      }
    }
    for (std::size_t j = 0; j < nj; ++j) {
      if (one_block) continue;
      // Several blocks: the sums become means, and the 95th percentile is selected
      // from the angles computed again, block by block (percentile()'s rank rule).
      ErrorStats& a = err[j].angle;
      if (a.count == 0) continue;
      const double count = static_cast<double>(a.count);
      a.mean /= count;
      a.rms = std::sqrt(a.rms / count);
      const double rank = 0.95 * (count - 1.0);
      const auto lo = static_cast<std::uint64_t>(std::floor(rank));
      const double frac = rank - static_cast<double>(lo);
      Block joint_block;
      std::vector<Quat> out(std::min(ns, bs));
      const auto [v0, v1] = select_two(
          [&](const auto& take) {
            for (std::size_t m0 = 0; m0 < ns; m0 += bs) {
              const std::size_t n = std::min(bs, ns - m0);
              joint_block.fill(R, m0, n, false, j);
              curves[j]->evaluate(joint_block.times().data(), n, out.data());
              (void)rotation_error(joint_block.rotation(R, j), out.data(), n, R.bone_axis[j], scratch);
              take(scratch.data(), n);  // the angles (in some order)
            }
          },
          lo);
      a.p95 = frac == 0.0 || lo + 1 >= a.count ? v0 : v0 + frac * (v1 - v0);
    }
    for (std::size_t j = 0; j < nj; ++j) {
      // With --loop the keys are the period's, not kf: the curve at them is computed again.
      const KeyJumps jumps = key_jumps(*curves[j], rebuilt[j].jump_times, R.cycle ? nullptr : at_keys[j].data());
      const RotationError& e = err[j];
      ErrorRow r;
      r.clip = R.clip_id;
      r.method = method;
      r.keep_every = keep;
      r.joint = skel.joints[j].name;
      r.frames = nf;
      r.samples = ns;
      r.mean_deg = e.angle.mean * kRadToDeg;
      r.rms_deg = e.angle.rms * kRadToDeg;
      r.p95_deg = e.angle.p95 * kRadToDeg;
      r.max_deg = e.angle.max * kRadToDeg;
      r.swing_rms_deg = e.swing.rms() * kRadToDeg;
      r.twist_rms_deg = e.twist.rms() * kRadToDeg;
      r.pos_rms = pose.joint_position[j].rms() * mpu;
      r.pos_max = pose.joint_position[j].max * mpu;
      r.pos_rms_pct = pose.joint_position[j].rms() * pct;
      r.pos_max_pct = pose.joint_position[j].max * pct;
      r.shell_rms = pose.joint_shell[j].rms() * mpu;
      r.shell_max = pose.joint_shell[j].max * mpu;
      r.acc_rms = smooth[j].rms() * kRadToDeg;
      r.acc_rms_ref = R.reference_acc_rms[j] * kRadToDeg;
      r.vel_jump_max = jumps.velocity * kRadToDeg;
      r.acc_jump_max = jumps.acceleration * kRadToDeg;
      r.height = R.height * mpu;
      r.metres_per_unit = mpu;
      r.unit = R.unit;
      r.keys = R.keys[j];
      r.motion_deg = R.motion_deg[j];
      if (R.cycle) fill_seam_columns(r, R, j, rebuilt[j]);
      rows.push_back(std::move(r));
    }
    ErrorRow* const joint_rows = rows.data() + rows.size() - nj;
    for (std::size_t f = 0; f < nfeet; ++f) {
      const FootContact c = foot_contact(feet_at[f].data(), R.frames.data(), nf, R.floor, R.metres_per_unit, options.feet);
      const FootContact& ref = R.foot_ref[f];
      ErrorRow& r = joint_rows[R.feet[f]];
      r.foot = true;
      r.contact_frames = static_cast<double>(c.contact);
      r.skate_frames = static_cast<double>(c.skating);
      r.skate_speed = c.mean_speed();
      r.contact_frames_ref = static_cast<double>(ref.contact);
      r.skate_frames_ref = static_cast<double>(ref.skating);
      r.skate_speed_ref = ref.mean_speed();
    }
    for (std::size_t e = 0; e < ne; ++e) {
      ErrorRow r;
      r.clip = R.clip_id;
      r.method = method;
      r.keep_every = keep;
      const EndSite& site = skel.end_sites[e];
      r.joint = site.name.empty() ? "EndSite_" + skel.joints[site.parent].name : site.name;
      r.end_site = true;
      r.frames = nf;
      r.samples = ns;
      r.pos_rms = pose.end_site_position[e].rms() * mpu;
      r.pos_max = pose.end_site_position[e].max * mpu;
      r.pos_rms_pct = pose.end_site_position[e].rms() * pct;
      r.pos_max_pct = pose.end_site_position[e].max * pct;
      r.height = R.height * mpu;
      r.metres_per_unit = mpu;
      r.unit = R.unit;
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

Result<PerFrameErrors> per_frame_errors(const ClipReference& R, const std::string& method, int keep) {
  const std::size_t nj = R.skeleton.joints.size(), ns = R.samples;
  PerFrameErrors out;
  out.angle.assign(nj, std::vector<double>(ns));
  out.times.resize(ns);
  for (std::size_t m = 0; m < ns; ++m) out.times[m] = sample_time(R, m);
  std::vector<Quat> test;
  Block block;
  for (std::size_t j = 0; j < nj; ++j) {
    auto curve = rebuild_joint(R, j, method, keep);
    if (!curve)
      return curve.failure(R.clip_id + ": joint '" + R.skeleton.joints[j].name + "', method " + method + ": ");
    const std::size_t bs = block_samples(R);
    for (std::size_t m0 = 0; m0 < ns; m0 += bs) {
      const std::size_t n = std::min(bs, ns - m0);
      block.fill(R, m0, n, false, j);
      test.resize(n);
      curve->curve->evaluate(block.times().data(), n, test.data());
      const Quat* ref = block.rotation(R, j);
      for (std::size_t m = 0; m < n; ++m) out.angle[j][m0 + m] = angular_distance(ref[m], test[m]) * kRadToDeg;
    }
  }
  return out;
}

Result<std::vector<ErrorRow>> evaluate_clip(const Clip& clip, const std::string& clip_id,
                                            const ClipEvalOptions& options) {
  auto reference = prepare_reference(clip, clip_id, options);
  if (!reference) return reference.failure();
  std::vector<ErrorRow> rows;
  for (const std::string& method : options.methods) {
    auto part = evaluate_method(*reference, method, options);
    if (!part) return part.failure();
    rows.insert(rows.end(), std::make_move_iterator(part->begin()), std::make_move_iterator(part->end()));
  }
  return rows;
}

}  // namespace rotinterp
