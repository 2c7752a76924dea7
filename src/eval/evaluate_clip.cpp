#include "rotinterp/eval/evaluate_clip.h"

#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {

constexpr double kRadToDeg = 180.0 / kPi;

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

// The original track at sorted times: its key at a key time, else the slerp of the
// two neighbouring keys; clamped outside the keys.
void sample_rotation(const RotationTrack& track, const std::vector<double>& times, Quat* out) {
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
    out[m] = slerp(track.keys[i], track.keys[i + 1], u);
  }
}

void sample_translation(const TranslationTrack& track, const std::vector<double>& times, Vec3* out) {
  const std::size_t n = track.times.size();
  std::size_t i = 0;
  for (std::size_t m = 0; m < times.size(); ++m) {
    const double t = times[m];
    while (i + 1 < n && track.times[i + 1] <= t) ++i;
    if (i + 1 >= n || t <= track.times[i]) {
      out[m] = (i + 1 >= n || t >= track.times[i]) ? track.keys[i] : track.keys[0];
      continue;
    }
    const double u = (t - track.times[i]) / (track.times[i + 1] - track.times[i]);
    out[m] = track.keys[i] + u * (track.keys[i + 1] - track.keys[i]);
  }
}

// Key frames for keep_every n: 0, n, 2n, … and the last.
std::vector<std::size_t> key_frames(std::size_t frames, std::size_t n) {
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < frames; i += n) k.push_back(i);
  if (frames > 0 && k.back() != frames - 1) k.push_back(frames - 1);
  return k;
}

}  // namespace

Result<std::vector<ErrorRow>> evaluate_clip(const Clip& clip, const std::string& clip_id,
                                            const ClipEvalOptions& options) {
  if (Status s = clip.validate(); !s) return make_error(clip_id + ": " + s.error());
  if (options.subframe < 0 || options.subframe > 1000)
    return make_error(clip_id + ": subframe must be between 0 and 1000");
  for (int n : options.keep_every)
    if (n < 1) return make_error(clip_id + ": keep_every must be at least 1");
  const Skeleton& skel = clip.skeleton;
  const std::size_t nj = skel.joints.size(), ne = skel.end_sites.size();

  // ---- the sample grid: frames, and subframes between them ----
  const std::vector<double> frames = frame_times(clip);
  const std::size_t nf = frames.size();
  const std::size_t per = static_cast<std::size_t>(options.subframe) + 1;  // samples per frame interval
  const std::size_t ns = nf == 0 ? 0 : (nf - 1) * per + 1;
  std::vector<double> times(ns);
  for (std::size_t m = 0; m < ns; ++m) {
    const std::size_t k = m / per, i = m % per;
    times[m] = i == 0 ? frames[k]
                      : frames[k] + (frames[k + 1] - frames[k]) * static_cast<double>(i) / static_cast<double>(per);
  }
  // Uniform spacing (for smoothness) only where the clip has a frame time.
  const double sample_dt = clip.frame_time > 0.0 ? clip.frame_time / static_cast<double>(per) : 0.0;

  // ---- the original at its frames (keys come from here) ----
  std::vector<std::vector<Quat>> orig(nj, std::vector<Quat>(nf));
  for (std::size_t j = 0; j < nj; ++j) sample_rotation(clip.rotations[j], frames, orig[j].data());

  // ---- the reference at every sample, joint-major ----
  std::vector<std::vector<Quat>> ref(nj, std::vector<Quat>(ns));
  std::vector<std::vector<Vec3>> ref_t(nj, std::vector<Vec3>(ns));
  if (options.truth) {
    std::vector<Quat> r(nj);
    std::vector<Vec3> t(nj);
    for (std::size_t m = 0; m < ns; ++m) {
      options.truth(times[m], r, t);
      if (r.size() != nj || t.size() != nj) return make_error(clip_id + ": the analytic truth has another skeleton");
      for (std::size_t j = 0; j < nj; ++j) {
        ref[j][m] = normalized_or_identity(r[j]);
        ref_t[j][m] = t[j].allFinite() ? t[j] : skel.joints[j].offset;
      }
    }
  } else {
    for (std::size_t j = 0; j < nj; ++j) {
      for (std::size_t m = 0; m < ns; ++m) {
        const std::size_t k = m / per, i = m % per;
        ref[j][m] = i == 0 ? orig[j][k]
                           : slerp(orig[j][k], orig[j][k + 1], static_cast<double>(i) / static_cast<double>(per));
      }
      if (clip.translations[j])
        sample_translation(*clip.translations[j], times, ref_t[j].data());
      else
        std::fill(ref_t[j].begin(), ref_t[j].end(), skel.joints[j].offset);
    }
  }

  // ---- reference world poses, computed once ----
  std::vector<WorldPose> ref_world(ns);
  std::vector<Quat> local_r(nj);
  std::vector<Vec3> local_t(nj);
  for (std::size_t m = 0; m < ns; ++m) {
    for (std::size_t j = 0; j < nj; ++j) {
      local_r[j] = ref[j][m];
      local_t[j] = ref_t[j][m];
    }
    forward_kinematics(skel, local_r, local_t, ref_world[m]);
  }

  double height = skeleton_height(rest_pose(skel));
  if (!(height > 0.0) && ns > 0) height = skeleton_height(ref_world[0]);
  if (!(height > 0.0)) height = 1.0;
  const double pct = 100.0 / height;
  const double shell_d = metres_in_clip_units(clip, options.shell_distance_m);
  const std::vector<Vec3> axes = bone_axes(skel);

  std::vector<double> ref_acc(nj, 0.0);
  for (std::size_t j = 0; j < nj; ++j) ref_acc[j] = sampled_smoothness(ref[j].data(), ns, sample_dt).acceleration_rms;

  std::vector<ErrorRow> rows;
  rows.reserve(options.methods.size() * options.keep_every.size() * (nj + ne));
  std::vector<std::vector<Quat>> test(nj, std::vector<Quat>(ns));
  std::vector<double> scratch;
  WorldPose test_world;
  for (const std::string& method : options.methods) {
    for (int keep : options.keep_every) {
      const std::vector<std::size_t> kf = key_frames(nf, static_cast<std::size_t>(keep));
      RotationTrack track;
      track.times.resize(kf.size());
      for (std::size_t i = 0; i < kf.size(); ++i) track.times[i] = frames[kf[i]];
      std::vector<KeyJumps> jumps(nj);
      std::vector<Smoothness> smooth(nj);
      for (std::size_t j = 0; j < nj; ++j) {
        track.keys.resize(kf.size());
        for (std::size_t i = 0; i < kf.size(); ++i) track.keys[i] = orig[j][kf[i]];
        track.make_sign_continuous();
        auto curve = make_interpolator(method, track);
        if (!curve)
          return make_error(clip_id + ": joint '" + skel.joints[j].name + "', method " + method + ": " + curve.error());
        (*curve)->evaluate(times.data(), ns, test[j].data());
        jumps[j] = key_jumps(**curve, track.times);
        smooth[j] = sampled_smoothness(test[j].data(), ns, sample_dt);
      }
      PoseError pose = make_pose_error(skel);
      for (std::size_t m = 0; m < ns; ++m) {
        for (std::size_t j = 0; j < nj; ++j) {
          local_r[j] = test[j][m];
          local_t[j] = ref_t[j][m];
        }
        forward_kinematics(skel, local_r, local_t, test_world);
        accumulate_pose_error(ref_world[m], test_world, shell_d, pose);
      }
      for (std::size_t j = 0; j < nj; ++j) {
        const RotationError e = rotation_error(ref[j].data(), test[j].data(), ns, axes[j], scratch);
        ErrorRow r;
        r.clip = clip_id;
        r.method = method;
        r.keep_every = keep;
        r.joint = skel.joints[j].name;
        r.frames = nf;
        r.samples = ns;
        r.mean_deg = e.angle.mean * kRadToDeg;
        r.rms_deg = e.angle.rms * kRadToDeg;
        r.p95_deg = e.angle.p95 * kRadToDeg;
        r.max_deg = e.angle.max * kRadToDeg;
        r.swing_rms_deg = e.swing.rms * kRadToDeg;
        r.twist_rms_deg = e.twist.rms * kRadToDeg;
        r.pos_rms = pose.joint_position[j].rms();
        r.pos_max = pose.joint_position[j].max;
        r.pos_rms_pct = r.pos_rms * pct;
        r.pos_max_pct = r.pos_max * pct;
        r.shell_rms = pose.joint_shell[j].rms();
        r.shell_max = pose.joint_shell[j].max;
        r.acc_rms = smooth[j].acceleration_rms * kRadToDeg;
        r.acc_rms_ref = ref_acc[j] * kRadToDeg;
        r.vel_jump_max = jumps[j].velocity * kRadToDeg;
        r.acc_jump_max = jumps[j].acceleration * kRadToDeg;
        r.height = height;
        rows.push_back(std::move(r));
      }
      for (std::size_t e = 0; e < ne; ++e) {
        ErrorRow r;
        r.clip = clip_id;
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
        r.height = height;
        rows.push_back(std::move(r));
      }
    }
  }
  return rows;
}

}  // namespace rotinterp
