// One method's rebuild of a clip from keys every N frames: the one rebuild eval
// measures (eval/evaluate_clip.h) and render draws (render/comparison.h).
//
// Frames and reference are those of clip/frames.h. Keys, with keep_every N:
//  * without a cycle, every joint keeps frames 0, N, 2N, … and the last
//    (keep_every_indices) and is rebuilt on the method's curve through them;
//  * with a cycle (the clip is one period of a loop, clip/loop.h), a joint that
//    closes keeps frames 0, N, 2N, … inside the period and is rebuilt on its
//    periodic curve (interp/periodic.h), which wraps to frame 0 one period later,
//    as resample --loop writes it; a joint that misses closure (a pop in the source)
//    is rebuilt as without a cycle, so its pop is kept and shows at the seam.
//
// Error. A joint's error at a frame is the angle between its reference rotation
// and the rebuilt one (angular_distance, in degrees). A frame's error is the mean
// and the largest of its joints' errors over the animated joints (those with more
// than one source key), or over every joint when none is animated.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/core/result.h"
#include "rotinterp/interp/interpolator.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// The cycle a clip is rebuilt as (eval --loop, render --loop).
struct CycleFrames {
  LoopCheck check;           // form, period (seconds), period_frames, joints that miss closure
  std::vector<bool> looped;  // [joint]: closes, so rebuilt on its periodic curve
};

// The cycle of `clip` in `form`, or in the form detected (nullopt). Errors (one
// line, starting "--loop: "): those of check_loop, and a clip that does not look
// like a cycle when the form is detected.
Result<CycleFrames> cycle_frames(const Clip& clip, std::optional<LoopForm> form);

// One joint rebuilt from its keys.
struct RebuiltJoint {
  RotationTrack keys;
  std::unique_ptr<Interpolator> curve;
  bool periodic = false;
  // The key times key_jumps (clip/metrics.h) reads: its interior keys are the keys
  // inside, not the seam (periodic: the keys, then frame 0 one period later).
  std::vector<double> jump_times;
};

// Joint `joint` of a clip whose frames are at `times` (seconds) with the source's
// rotation `source` at each, rebuilt by `method` with keep_every ≥ 1 (less reads
// as 1) as above; `cycle` is the clip's cycle, or null. Errors: the method's.
Result<RebuiltJoint> rebuild_joint(const std::vector<double>& times, const std::vector<Quat>& source,
                                   const std::string& method, std::size_t keep_every, const CycleFrames* cycle,
                                   std::size_t joint);

// The frames where the keys of keep_every N lie: without a cycle every Nth and the
// last; with one, the period's, then the wrap-around frame at t₀ + P where the clip
// has it (the closed form's last frame).
std::vector<std::size_t> key_frames(const std::vector<double>& times, std::size_t keep_every,
                                    const CycleFrames* cycle);

// A frame's error, degrees (see the top of this file).
struct FrameError {
  double mean = 0.0;
  double max = 0.0;
};

// A clip's reference at every frame and several methods' curves on those frames:
// rotations, translations, poses and errors per frame, for render's panels.
class RebuiltClip {
 public:
  // The curve of a method for a joint.
  using CurveFn = std::function<Result<std::unique_ptr<Interpolator>>(const std::string& method, std::size_t joint)>;

  // Each of `methods` rebuilt from `clip`'s frames as above, without a cycle. `clip`
  // must outlive the result. Errors name the method and the joint.
  static Result<RebuiltClip> build(const Clip& clip, const std::vector<std::string>& methods, std::size_t keep_every);
  // The same for curves made elsewhere on `clip`'s timeline (render --loop plays a
  // cycle twice), whose keys lie at the frames `keys`.
  static Result<RebuiltClip> build(const Clip& clip, const std::vector<std::string>& methods,
                                   std::vector<std::size_t> keys, const CurveFn& curve);

  const Skeleton& skeleton() const { return *skeleton_; }
  std::size_t frames() const { return reference_.grid.size(); }
  double time(std::size_t f) const { return reference_.grid.times[f]; }
  const std::vector<std::size_t>& keys() const { return keys_; }  // key frames, sorted
  bool animated(std::size_t joint) const { return animated_[joint]; }
  const Quat& reference_rotation(std::size_t joint, std::size_t f) const { return reference_.rotation[joint][f]; }
  const Vec3& bone_axis(std::size_t joint) const { return bone_axis_[joint]; }
  Quat method_rotation(std::size_t m, std::size_t joint, std::size_t f) const;

  // Every joint's translation at frame f: the reference's for every method (only
  // rotations are rebuilt).
  std::vector<Vec3> translations(std::size_t f) const;

  void reference_pose(std::size_t f, WorldPose& out) const;

  // Method m's rotations at frame f into `local`, and its frame error; with
  // `joint_error`, every joint's error (degrees), and with `worst`, the counted
  // joint that errs most (-1 when none is counted).
  FrameError method_rotations(std::size_t m, std::size_t f, std::vector<Quat>& local,
                              std::vector<double>* joint_error = nullptr, int* worst = nullptr) const;
  // The same, and the pose they give with the reference's translations.
  FrameError method_pose(std::size_t m, std::size_t f, WorldPose& out, std::vector<double>* joint_error = nullptr,
                         int* worst = nullptr) const;

 private:
  // The reference side of `clip`, its keys at `keys`, no curves yet.
  static RebuiltClip reference_of(const Clip& clip, std::vector<std::size_t> keys);
  Status add_curves(const std::vector<std::string>& methods, const CurveFn& curve);

  const Skeleton* skeleton_ = nullptr;
  DenseClip reference_;                        // the reference at every frame
  std::vector<Vec3> bone_axis_;                // [joint]
  std::vector<std::size_t> keys_;
  std::vector<bool> animated_;                 // [joint]
  bool any_animated_ = false;
  std::vector<std::vector<std::unique_ptr<Interpolator>>> curves_;  // [method][joint]
};

}  // namespace rotinterp
