#include "rotinterp/eval/evaluate_clip.h"

#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace rotinterp {

namespace {

constexpr double kRadToDeg = 180.0 / kPi;

// A frame time within this fraction of a key interval from a key takes the key
// itself: frame grids computed as start + k·frame_time differ from a reader's key
// times by round-off (~1e-16 relative), which must not turn keys into slerps.
constexpr double kSnap = 1e-9;

// Frame times of the original clip (see the header).
std::vector<double> frame_times(const Clip& clip) {
  std::vector<double> t;
  if (clip.frame_time > 0.0) {
    const std::size_t n = clip.frame_count();
    const double start = clip.start_time(), end = clip.end_time();
    t.resize(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = std::min(start + static_cast<double>(k) * clip.frame_time, end);
    if (n > 1) t[n - 1] = end;
    return t;
  }
  const RotationTrack* longest = &clip.rotations.front();
  for (const RotationTrack& r : clip.rotations)
    if (r.times.size() > longest->times.size()) longest = &r;
  return longest->times;
}

// q0 → q1 along the shortest arc, at fraction u: q0·exp(u·log(q0⁻¹q1)). Exactly q0 at u = 0.
Quat slerp(const Quat& q0, const Quat& q1, double u) {
  if (u == 0.0) return q0;
  return apply_moving(q0, displacement_moving(q0, q1) * u);
}

// A track (rotation or translation) at sorted times: its key at a key time, else
// `blend` of the two neighbouring keys at the fraction between them; clamped
// outside the keys.
template <class Track, class Value, class Blend>
void sample_track(const Track& track, const std::vector<double>& times, Value* out, Blend blend) {
  const std::size_t n = track.times.size();
  std::size_t i = 0;  // segment [i, i+1]
  for (std::size_t m = 0; m < times.size(); ++m) {
    const double t = times[m];
    while (i + 1 < n && track.times[i + 1] <= t) ++i;
    if (i + 1 >= n || t <= track.times[i]) {
      out[m] = (i + 1 >= n || t >= track.times[i]) ? track.keys[i] : track.keys[0];
      continue;
    }
    const double u = (t - track.times[i]) / (track.times[i + 1] - track.times[i]);
    out[m] = u < kSnap ? track.keys[i] : u > 1.0 - kSnap ? track.keys[i + 1] : blend(track.keys[i], track.keys[i + 1], u);
  }
}

// The original's rotations: slerp between keys.
void sample_rotation(const RotationTrack& track, const std::vector<double>& times, Quat* out) {
  sample_track(track, times, out, slerp);
}

// The original's translations: linear between keys.
void sample_translation(const TranslationTrack& track, const std::vector<double>& times, Vec3* out) {
  sample_track(track, times, out, [](const Vec3& a, const Vec3& b, double u) -> Vec3 { return a + u * (b - a); });
}

}  // namespace

std::vector<std::size_t> key_frames(std::size_t frames, int keep_every) {
  const auto n = static_cast<std::size_t>(std::max(keep_every, 1));
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < frames; i += n) k.push_back(i);
  if (frames > 0 && k.back() != frames - 1) k.push_back(frames - 1);
  return k;
}

Result<ClipReference> prepare_reference(const Clip& clip, const std::string& clip_id,
                                        const ClipEvalOptions& options) {
  if (Status s = clip.validate(); !s) return make_error(clip_id + ": " + s.error());
  if (options.subframe < 0 || options.subframe > 1000)
    return make_error(clip_id + ": subframe must be between 0 and 1000");
  ClipReference R;
  R.clip_id = clip_id;
  R.skeleton = clip.skeleton;
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size();

  // ---- the sample grid: frames, and subframes between them ----
  R.frames = frame_times(clip);
  const std::size_t nf = R.frames.size();
  const std::size_t per = R.per_frame = static_cast<std::size_t>(options.subframe) + 1;
  const std::size_t ns = nf == 0 ? 0 : (nf - 1) * per + 1;
  R.times.resize(ns);
  for (std::size_t m = 0; m < ns; ++m) {
    const std::size_t k = m / per, i = m % per;
    R.times[m] = i == 0 ? R.frames[k]
                        : R.frames[k] + (R.frames[k + 1] - R.frames[k]) * static_cast<double>(i) / static_cast<double>(per);
  }
  R.sample_dt = clip.frame_time > 0.0 ? clip.frame_time / static_cast<double>(per) : 0.0;

  // ---- the original at its frames (keys come from here) ----
  R.original.assign(nj, std::vector<Quat>(nf));
  for (std::size_t j = 0; j < nj; ++j) sample_rotation(clip.rotations[j], R.frames, R.original[j].data());

  // ---- the reference at every sample, joint-major ----
  R.reference.assign(nj, std::vector<Quat>(ns));
  R.translation.assign(nj, std::vector<Vec3>(ns));
  if (options.truth) {
    std::vector<Quat> r(nj);
    std::vector<Vec3> t(nj);
    for (std::size_t m = 0; m < ns; ++m) {
      options.truth(R.times[m], r, t);
      if (r.size() != nj || t.size() != nj) return make_error(clip_id + ": the analytic truth has another skeleton");
      for (std::size_t j = 0; j < nj; ++j) {
        R.reference[j][m] = normalized_or_identity(r[j]);
        R.translation[j][m] = t[j].allFinite() ? t[j] : skel.joints[j].offset;
      }
    }
  } else {
    for (std::size_t j = 0; j < nj; ++j) {
      for (std::size_t m = 0; m < ns; ++m) {
        const std::size_t k = m / per, i = m % per;
        R.reference[j][m] = i == 0 ? R.original[j][k]
                                   : slerp(R.original[j][k], R.original[j][k + 1],
                                           static_cast<double>(i) / static_cast<double>(per));
      }
      if (clip.translations[j])
        sample_translation(*clip.translations[j], R.times, R.translation[j].data());
      else
        std::fill(R.translation[j].begin(), R.translation[j].end(), skel.joints[j].offset);
    }
  }

  // ---- reference world poses, computed once ----
  R.world.resize(ns);
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  for (std::size_t m = 0; m < ns; ++m) {
    for (std::size_t j = 0; j < nj; ++j) {
      local_r[j] = R.reference[j][m];
      local_t[j] = R.translation[j][m];
    }
    forward_kinematics(skel, local_r, local_t, R.world[m]);
  }

  R.height = skeleton_height(rest_pose(skel));
  if (!(R.height > 0.0) && ns > 0) R.height = skeleton_height(R.world[0]);
  if (!(R.height > 0.0)) R.height = 1.0;
  R.shell_distance = metres_in_clip_units(clip, options.shell_distance_m);
  R.bone_axis = bone_axes(skel);
  R.reference_acc_rms.assign(nj, 0.0);
  for (std::size_t j = 0; j < nj; ++j)
    R.reference_acc_rms[j] = sampled_smoothness(R.reference[j].data(), ns, R.sample_dt).acceleration_rms;
  return R;
}

RotationTrack decimated_track(const ClipReference& R, std::size_t joint, int keep_every) {
  const std::vector<std::size_t> kf = key_frames(R.frames.size(), keep_every);
  RotationTrack track;
  track.times.resize(kf.size());
  track.keys.resize(kf.size());
  for (std::size_t i = 0; i < kf.size(); ++i) {
    track.times[i] = R.frames[kf[i]];
    track.keys[i] = R.original[joint][kf[i]];
  }
  track.make_sign_continuous();
  return track;
}

Result<std::vector<ErrorRow>> evaluate_method(const ClipReference& R, const std::string& method,
                                              const ClipEvalOptions& options) {
  const Skeleton& skel = R.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size();
  const std::size_t nf = R.frames.size(), ns = R.times.size();
  const double pct = 100.0 / R.height;
  for (int n : options.keep_every)
    if (n < 1) return make_error(R.clip_id + ": keep_every must be at least 1");

  std::vector<ErrorRow> rows;
  rows.reserve(options.keep_every.size() * (nj + ne));
  std::vector<std::vector<Quat>> test(nj, std::vector<Quat>(ns));
  std::vector<double> scratch;
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  WorldPose test_world;
  std::vector<Quat> at_keys;
  for (int keep : options.keep_every) {
    const std::vector<std::size_t> kf = key_frames(nf, keep);
    at_keys.resize(kf.size());
    std::vector<KeyJumps> jumps(nj);
    std::vector<Smoothness> smooth(nj);
    for (std::size_t j = 0; j < nj; ++j) {
      const RotationTrack track = decimated_track(R, j, keep);
      auto curve = make_interpolator(method, track);
      if (!curve)
        return make_error(R.clip_id + ": joint '" + skel.joints[j].name + "', method " + method + ": " + curve.error());
      (*curve)->evaluate(R.times.data(), ns, test[j].data());
      // The curve at its keys is among the samples (frame kf[i] is sample kf[i]·per_frame).
      for (std::size_t i = 0; i < kf.size(); ++i) at_keys[i] = test[j][kf[i] * R.per_frame];
      jumps[j] = key_jumps(**curve, track.times, at_keys.data());
      smooth[j] = sampled_smoothness(test[j].data(), ns, R.sample_dt);
    }
    PoseError pose = make_pose_error(skel);
    for (std::size_t m = 0; m < ns; ++m) {
      bool equal = true;  // the rebuilt pose is the reference's, bit for bit (at keys)
      for (std::size_t j = 0; j < nj; ++j) {
        local_r[j] = test[j][m];
        local_t[j] = R.translation[j][m];
        equal = equal && local_r[j].coeffs() == R.reference[j][m].coeffs();
      }
      if (equal) {
        accumulate_equal_poses(pose);
        continue;
      }
      forward_kinematics(skel, local_r, local_t, test_world);
      accumulate_pose_error(R.world[m], test_world, R.shell_distance, pose);
    }
    for (std::size_t j = 0; j < nj; ++j) {
      const RotationError e = rotation_error(R.reference[j].data(), test[j].data(), ns, R.bone_axis[j], scratch);
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
      r.pos_rms = pose.joint_position[j].rms();
      r.pos_max = pose.joint_position[j].max;
      r.pos_rms_pct = r.pos_rms * pct;
      r.pos_max_pct = r.pos_max * pct;
      r.shell_rms = pose.joint_shell[j].rms();
      r.shell_max = pose.joint_shell[j].max;
      r.acc_rms = smooth[j].acceleration_rms * kRadToDeg;
      r.acc_rms_ref = R.reference_acc_rms[j] * kRadToDeg;
      r.vel_jump_max = jumps[j].velocity * kRadToDeg;
      r.acc_jump_max = jumps[j].acceleration * kRadToDeg;
      r.height = R.height;
      rows.push_back(std::move(r));
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
      r.pos_rms = pose.end_site_position[e].rms();
      r.pos_max = pose.end_site_position[e].max;
      r.pos_rms_pct = r.pos_rms * pct;
      r.pos_max_pct = r.pos_max * pct;
      r.height = R.height;
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

Result<std::vector<ErrorRow>> evaluate_clip(const Clip& clip, const std::string& clip_id,
                                            const ClipEvalOptions& options) {
  auto reference = prepare_reference(clip, clip_id, options);
  if (!reference) return make_error(reference.error());
  std::vector<ErrorRow> rows;
  for (const std::string& method : options.methods) {
    auto part = evaluate_method(*reference, method, options);
    if (!part) return make_error(part.error());
    rows.insert(rows.end(), std::make_move_iterator(part->begin()), std::make_move_iterator(part->end()));
  }
  return rows;
}

}  // namespace rotinterp
