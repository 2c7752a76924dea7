// One method evaluated on a clip's reference: its rows of errors.csv, and its error at every sample (--per-frame).
#include "rotinterp/eval/evaluate_clip.h"

#include "pose_pass.h"
#include "sample_block.h"
#include "streamed_stats.h"

#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <utility>

namespace rotinterp {

using detail::Block;
using detail::block_samples;
using detail::select_two;
using detail::SmoothnessSum;

namespace {

constexpr double kRadToDeg = 180.0 / kPi;

// What one spacing's pass over the samples sums, per joint.
struct SpacingSums {
  std::vector<RebuiltJoint> rebuilt;       // eval/seam.h: periodic curves with --loop
  std::vector<std::vector<Quat>> at_keys;  // [joint][key]: the curve at its key frames
  std::vector<SmoothnessSum> smooth;
  std::vector<RotationError> err;          // summed over blocks: angle sums in mean·count, rms²·count
  PoseError pose;
};

// With several blocks: the angle's sums become means, and the 95th percentile is
// selected from joint j's angles computed again, block by block (percentile()'s rank rule).
void finish_angles(const ClipReference& R, std::size_t j, const Interpolator& curve, ErrorStats& a) {
  const std::size_t ns = R.samples, bs = block_samples(R);
  std::vector<double> scratch;
  if (a.count == 0) return;
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
          curve.evaluate(joint_block.times().data(), n, out.data());
          (void)rotation_error(joint_block.rotation(R, j), out.data(), n, R.bone_axis[j], scratch, false);
          take(scratch.data(), n);  // the angles (in some order)
        }
      },
      lo);
  a.p95 = frac == 0.0 || lo + 1 >= a.count ? v0 : v0 + frac * (v1 - v0);
}

// One spacing's rows: a row per joint, the feet's contact columns on their joints'
// rows (feet_at: [foot][frame], the rebuilt feet), then a row per End Site.
void append_rows(const ClipReference& R, const std::string& method, int keep, const ClipEvalOptions& options,
                 const SpacingSums& sums, const std::vector<std::vector<Vec3>>& feet_at, std::vector<ErrorRow>& rows) {
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size(), nfeet = R.feet.size();
  const std::size_t nf = R.frames.size(), ns = R.samples;
  const double pct = 100.0 / R.height;
  const double mpu = R.metres_per_unit;  // the rows are in metres
  for (std::size_t j = 0; j < nj; ++j) {
    // With --loop the keys are the period's, not kf: the curve at them is computed again.
    const KeyJumps jumps = R.metrics.has(Metric::smoothness)
                               ? key_jumps(*sums.rebuilt[j].curve, sums.rebuilt[j].jump_times,
                                           R.cycle ? nullptr : sums.at_keys[j].data())
                               : KeyJumps{};
    const RotationError& e = sums.err[j];
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
    if (R.metrics.needs_poses()) {
      r.pos_rms = sums.pose.joint_position[j].rms() * mpu;
      r.pos_max = sums.pose.joint_position[j].max * mpu;
      r.pos_rms_pct = sums.pose.joint_position[j].rms() * pct;
      r.pos_max_pct = sums.pose.joint_position[j].max * pct;
      r.shell_rms = sums.pose.joint_shell[j].rms() * mpu;
      r.shell_max = sums.pose.joint_shell[j].max * mpu;
    }
    r.acc_rms = sums.smooth[j].rms() * kRadToDeg;
    r.acc_rms_ref = R.reference_acc_rms[j] * kRadToDeg;
    r.vel_jump_max = jumps.velocity * kRadToDeg;
    r.acc_jump_max = jumps.acceleration * kRadToDeg;
    r.height = R.height * mpu;
    r.metres_per_unit = mpu;
    r.unit = R.unit;
    r.keys = R.keys[j];
    r.motion_deg = R.motion_deg[j];
    if (R.cycle && R.metrics.has(Metric::seam)) fill_seam_columns(r, R, j, sums.rebuilt[j]);
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
  for (std::size_t e = 0; e < (R.metrics.has(Metric::fk) ? ne : 0); ++e) {  // End Site rows hold fk alone
    ErrorRow r;
    r.clip = R.clip_id;
    r.method = method;
    r.keep_every = keep;
    const EndSite& site = skel.end_sites[e];
    r.joint = site.name.empty() ? "EndSite_" + skel.joints[site.parent].name : site.name;
    r.end_site = true;
    r.frames = nf;
    r.samples = ns;
    r.pos_rms = sums.pose.end_site_position[e].rms() * mpu;
    r.pos_max = sums.pose.end_site_position[e].max * mpu;
    r.pos_rms_pct = sums.pose.end_site_position[e].rms() * pct;
    r.pos_max_pct = sums.pose.end_site_position[e].max * pct;
    r.height = R.height * mpu;
    r.metres_per_unit = mpu;
    r.unit = R.unit;
    rows.push_back(std::move(r));
  }
}

}  // namespace

std::vector<int> skipped_spacings(std::size_t frames, const ClipEvalOptions& options) {
  std::vector<int> out;
  for (int n : options.keep_every)
    if (frames < options.min_frames || frames < 2 * static_cast<std::size_t>(std::max(n, 1)) + 1) out.push_back(n);
  return out;
}

Result<std::vector<ErrorRow>> evaluate_method(const ClipReference& R, const std::string& method,
                                              const ClipEvalOptions& options) {
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size();
  const std::size_t nf = R.frames.size(), ns = R.samples;
  for (int n : options.keep_every)
    if (n < 1) return make_error(R.clip_id + ": keep_every must be at least 1");

  const std::size_t bs = block_samples(R);
  const bool one_block = ns <= bs;
  // What R.metrics asks for: the rotation error (its swing and twist apart), the
  // smoothness sums with the curve at its keys, the pose pass.
  const bool swing_twist = R.metrics.has(Metric::swing_twist);
  const bool rotations = swing_twist || R.metrics.has(Metric::angle);
  const bool smoothness = R.metrics.has(Metric::smoothness), poses_needed = R.metrics.needs_poses();
  std::vector<ErrorRow> rows;
  rows.reserve(options.keep_every.size() * (nj + ne));
  // test[j]: two samples carried from the previous block (for smoothness), then the block.
  std::vector<std::vector<Quat>> test(nj, std::vector<Quat>(2 + std::min(ns, bs)));
  std::vector<const Quat*> test_at(nj);  // test[j]'s block
  for (std::size_t j = 0; j < nj; ++j) test_at[j] = test[j].data() + 2;
  std::vector<double> scratch;
  detail::PosePass poses;
  Block block;
  const std::vector<int> skipped = skipped_spacings(nf, options);
  const std::size_t nfeet = R.feet.size();
  std::vector<std::vector<Vec3>> feet_at(nfeet, std::vector<Vec3>(nf));  // [foot][frame], rebuilt
  for (int keep : options.keep_every) {
    if (std::find(skipped.begin(), skipped.end(), keep) != skipped.end()) continue;
    const std::vector<std::size_t> kf = keep_every_indices(nf, static_cast<std::size_t>(keep));
    SpacingSums sums;
    sums.rebuilt.resize(nj);
    std::vector<const Interpolator*> curves(nj);
    for (std::size_t j = 0; j < nj; ++j) {
      auto joint = rebuild_joint(R, j, method, keep);
      if (!joint)
        return joint.failure(R.clip_id + ": joint '" + skel.joints[j].name + "', method " + method + ": ");
      sums.rebuilt[j] = std::move(*joint);
      curves[j] = sums.rebuilt[j].curve.get();
    }
    sums.at_keys.assign(smoothness ? nj : 0, std::vector<Quat>(kf.size()));
    sums.smooth.resize(nj);
    sums.err.resize(nj);
    if (poses_needed) sums.pose = make_pose_error(skel);
    for (std::size_t m0 = 0; m0 < ns; m0 += bs) {
      const std::size_t n = std::min(bs, ns - m0);
      block.fill(R, m0, n, poses_needed);
      const std::size_t carry = m0 == 0 ? 0 : 2;
      for (std::size_t j = 0; j < nj; ++j) {
        Quat* out = test[j].data() + 2;
        curves[j]->evaluate(block.times().data(), n, out);
        if (smoothness) {
          // The curve at its keys is among the samples (frame kf[i] is sample kf[i]·per_frame).
          for (std::size_t i = 0; i < kf.size(); ++i)
            if (const std::size_t s = kf[i] * R.per_frame; s >= m0 && s < m0 + n) sums.at_keys[j][i] = out[s - m0];
          sums.smooth[j].add(out - carry, n + carry, R.sample_dt);
        }
        if (rotations) {
          const RotationError e = rotation_error(block.rotation(R, j), out, n, R.bone_axis[j], scratch, swing_twist);
          if (one_block) {
            sums.err[j] = e;
          } else {
            ErrorStats& a = sums.err[j].angle;
            const double c = static_cast<double>(e.angle.count);
            a.mean += e.angle.mean * c;  // sums until the end
            a.rms += e.angle.rms * e.angle.rms * c;
            a.max = std::max(a.max, e.angle.max);
            a.count += e.angle.count;
            for (auto [sum, part] : {std::pair{&sums.err[j].swing, &e.swing}, {&sums.err[j].twist, &e.twist}}) {
              sum->count += part->count;
              sum->sum += part->sum;
              sum->sum_sq += part->sum_sq;
              sum->max = std::max(sum->max, part->max);
            }
          }
        }
        test[j][0] = n >= 2 ? out[n - 2] : test[j][1];
        test[j][1] = out[n - 1];
      }
      if (poses_needed) poses.add(R, block, m0, n, test_at.data(), sums.pose, feet_at);
    }
    if (!one_block && R.metrics.has(Metric::angle))
      for (std::size_t j = 0; j < nj; ++j) finish_angles(R, j, *curves[j], sums.err[j].angle);
    append_rows(R, method, keep, options, sums, feet_at, rows);
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
