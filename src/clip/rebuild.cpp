// The one rebuild of a clip from keys every N frames (with or without a cycle), and its errors per frame.
#include "rotinterp/clip/rebuild.h"

#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/periodic.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

Result<CycleFrames> cycle_frames(const Clip& clip, std::optional<LoopForm> form) {
  auto check = check_loop(clip, form);
  if (!check) return check.failure("--loop: ");
  if (!form && !check->looks_like_cycle)
    return make_error("--loop: the clip does not look like a cycle: " + loop_check_text(*check) +
                      " (give --loop closed or --loop open to treat it as one)");
  CycleFrames c;
  c.check = std::move(*check);
  c.looped.assign(clip.skeleton.joints.size(), true);
  for (const ClosureMiss& m : c.check.misses) c.looped[m.joint] = false;
  return c;
}

namespace {

// With a cycle: the key frames inside the period (0, N, 2N, … before t₀ + P), by
// time — a clip without a frame time has its key times as frames (clip/frames.h),
// not the cycle's period_frames — and whether the clip has a frame at t₀ + P.
std::vector<std::size_t> period_keys(const std::vector<double>& times, const LoopCheck& c, std::size_t n,
                                     bool& wrap_frame) {
  const double half_frame = 0.5 * c.period / static_cast<double>(c.period_frames);
  const double end = times.front() + c.period - half_frame;
  std::vector<std::size_t> kf;
  for (std::size_t k = 0; k < times.size() && times[k] < end; k += n) kf.push_back(k);
  wrap_frame = std::abs(times.back() - (end + half_frame)) < half_frame;
  return kf;
}

}  // namespace

std::vector<std::size_t> key_frames(const std::vector<double>& times, std::size_t keep_every,
                                    const CycleFrames* cycle) {
  const std::size_t n = std::max<std::size_t>(keep_every, 1);
  if (!cycle || times.empty()) return keep_every_indices(times.size(), n);
  bool wrap_frame = false;
  std::vector<std::size_t> kf = period_keys(times, cycle->check, n, wrap_frame);
  if (wrap_frame && kf.back() != times.size() - 1) kf.push_back(times.size() - 1);
  return kf;
}

Result<RebuiltJoint> rebuild_joint(const std::vector<double>& times, const std::vector<Quat>& source,
                                   const std::string& method, std::size_t keep_every, const CycleFrames* cycle,
                                   std::size_t joint) {
  const std::size_t n = std::max<std::size_t>(keep_every, 1);
  RebuiltJoint out;
  out.periodic = cycle && cycle->looped[joint];
  bool wrap_frame = false;
  const std::vector<std::size_t> kf =
      out.periodic ? period_keys(times, cycle->check, n, wrap_frame) : keep_every_indices(times.size(), n);
  out.keys = decimated_track(times, source, kf);
  auto curve = make_joint_curve(method, out.keys, out.periodic ? std::optional<double>(cycle->check.period) : std::nullopt);
  if (!curve) return curve.failure();
  out.curve = std::move(*curve);
  out.jump_times = out.keys.times;
  if (out.periodic) out.jump_times.push_back(times.front() + cycle->check.period);
  return out;
}

RebuiltClip RebuiltClip::reference_of(const Clip& clip, std::vector<std::size_t> keys) {
  RebuiltClip r;
  r.skeleton_ = &clip.skeleton;
  r.reference_ = dense_clip(clip);
  r.bone_axis_ = bone_axes(clip.skeleton);
  r.keys_ = std::move(keys);
  const std::size_t joints = clip.skeleton.joints.size();
  r.animated_.resize(joints);
  for (std::size_t j = 0; j < joints; ++j) {
    r.animated_[j] = clip.rotations[j].keys.size() > 1;
    r.any_animated_ = r.any_animated_ || r.animated_[j];
  }
  return r;
}

Status RebuiltClip::add_curves(const std::vector<std::string>& methods, const CurveFn& curve) {
  curves_.resize(methods.size());
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (std::size_t j = 0; j < animated_.size(); ++j) {
      auto made = curve(methods[m], j);
      if (!made) return made.failure(methods[m] + ", joint " + skeleton_->joints[j].name + ": ");
      curves_[m].push_back(std::move(made).value());
    }
  return Ok{};
}

Result<RebuiltClip> RebuiltClip::build(const Clip& clip, const std::vector<std::string>& methods,
                                       std::size_t keep_every) {
  const std::size_t frames = frame_grid(clip).size();
  RebuiltClip r = reference_of(clip, keep_every_indices(frames, std::max<std::size_t>(keep_every, 1)));
  const DenseClip& reference = r.reference_;
  Status s = r.add_curves(methods, [&](const std::string& method, std::size_t joint) -> Result<std::unique_ptr<Interpolator>> {
    auto rebuilt = rebuild_joint(reference.grid.times, reference.rotation[joint], method, keep_every, nullptr, joint);
    if (!rebuilt) return rebuilt.failure();
    return std::move(rebuilt->curve);
  });
  if (!s) return s.failure();
  return r;
}

Result<RebuiltClip> RebuiltClip::build(const Clip& clip, const std::vector<std::string>& methods,
                                       std::vector<std::size_t> keys, const CurveFn& curve) {
  RebuiltClip r = reference_of(clip, std::move(keys));
  if (Status s = r.add_curves(methods, curve); !s) return s.failure();
  return r;
}

Quat RebuiltClip::method_rotation(std::size_t m, std::size_t joint, std::size_t f) const {
  return curves_[m][joint]->evaluate(time(f));
}

std::vector<Vec3> RebuiltClip::translations(std::size_t f) const {
  std::vector<Vec3> t(reference_.translation.size());
  for (std::size_t j = 0; j < t.size(); ++j) t[j] = reference_.translation[j][f];
  return t;
}

void RebuiltClip::reference_pose(std::size_t f, WorldPose& out) const {
  std::vector<Quat> local(reference_.rotation.size());
  for (std::size_t j = 0; j < local.size(); ++j) local[j] = reference_.rotation[j][f];
  forward_kinematics(*skeleton_, local, translations(f), out);
}

FrameError RebuiltClip::method_rotations(std::size_t m, std::size_t f, std::vector<Quat>& local,
                                         std::vector<double>* joint_error, int* worst) const {
  local.resize(reference_.rotation.size());
  if (joint_error) joint_error->assign(local.size(), 0.0);
  if (worst) *worst = -1;
  FrameError error;
  std::size_t counted = 0;
  for (std::size_t j = 0; j < local.size(); ++j) {
    local[j] = method_rotation(m, j, f);
    const double e = angular_distance(reference_.rotation[j][f], local[j]) * 180.0 / kPi;
    if (joint_error) (*joint_error)[j] = e;
    if (animated_[j] || !any_animated_) {
      error.mean += e;
      if (worst && (*worst < 0 || e > error.max)) *worst = static_cast<int>(j);
      error.max = std::max(error.max, e);
      ++counted;
    }
  }
  if (counted) error.mean /= static_cast<double>(counted);
  return error;
}

FrameError RebuiltClip::method_pose(std::size_t m, std::size_t f, WorldPose& out, std::vector<double>* joint_error,
                                    int* worst) const {
  std::vector<Quat> local;
  const FrameError error = method_rotations(m, f, local, joint_error, worst);
  forward_kinematics(*skeleton_, local, translations(f), out);
  return error;
}

}  // namespace rotinterp
