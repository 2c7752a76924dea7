// Evaluating one clip: decimate, rebuild with each method, measure (clip/metrics.h).
//
// The clip's frames, the original's value at each and the key frames for
// keep_every N are those of clip/frames.h, shared with render and resample. Each
// method is built per joint on those keys by the rebuild render draws too
// (clip/rebuild.h), and evaluated at every frame and, with subframe K,
// at K evenly spaced times between consecutive frames, where the reference is the
// slerp of the two original frames (or `truth`, when given, everywhere).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/core/result.h"
#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/foot_skating.h"
#include "rotinterp/eval/metric_set.h"
#include "rotinterp/eval/seam.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// The exact local rotation and translation of every joint at time t (seconds):
// analytic truth for synthetic clips.
using TruthFn = std::function<void(double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation)>;

struct ClipEvalOptions {
  std::vector<std::string> methods;  // registry names, evaluated in this order
  std::vector<int> keep_every;       // each ≥ 1, in this order
  MetricSet metrics = MetricSet::all();  // computed and reported; the others are not computed
  int subframe = 0;                  // extra samples between consecutive frames (0 … 1000)
  double shell_distance_m = kDefaultShellDistanceMetres;  // metres, converted by Clip::unit
  TruthFn truth;                     // optional reference instead of the clip's frames
  std::size_t min_frames = 0;        // clips with fewer frames are skipped (see skipped_spacings)
  FootContactOptions feet;           // foot joints, contact thresholds, floor
  // eval --loop (eval/seam.h): the clip is one period of a cycle, in loop_form or the
  // form detected; the rows carry the seam columns.
  bool loop = false;
  std::optional<LoopForm> loop_form;
};

// The spacings of options.keep_every a clip of `frames` frames is not evaluated at:
// those that leave no frame between keys to rebuild twice over (frames < 2N + 1: at
// most one key interval of N frames), and all of them when frames < min_frames.
std::vector<int> skipped_spacings(std::size_t frames, const ClipEvalOptions& options);

// The reference side of one clip, computed once and shared (read-only) by the
// methods: frame times, the original at its frames, the reference at every frame
// (joint-major) and its world poses, and the per-clip constants. Subframe samples
// (subframe K > 0) are not stored: evaluate_method computes them block by block
// from what is kept here, so memory is bounded by the clip, not by K.
struct ClipReference {
  std::string clip_id;
  Skeleton skeleton;
  std::vector<double> frames;                 // frame times, seconds
  std::size_t per_frame = 1;                  // samples per frame interval (subframe + 1)
  std::size_t samples = 0;                    // (frames − 1)·per_frame + 1; sample k·per_frame is frame k
  double sample_dt = 0;                       // uniform sample spacing (s), 0 if the clip has no frame time
  std::vector<std::vector<Quat>> original;    // [joint][frame]: where keys are taken
  std::vector<std::vector<Quat>> reference;   // [joint][frame]
  std::vector<std::vector<Vec3>> translation; // [joint][frame]: used for both sides
  MetricSet metrics = MetricSet::all();       // what is prepared (and measured): options.metrics
  std::vector<WorldPose> world;               // [frame]: forward kinematics of the reference (metrics.needs_poses())
  std::vector<Vec3> bone_axis;                // [joint], see bone_axes()
  std::vector<double> reference_acc_rms;      // [joint], rad/s² (0 without smoothness)
  double height = 1;                          // clip units
  double shell_distance = 0;                  // clip units
  // Where subframe samples come from (per_frame > 1): the analytic truth when
  // given, else the slerp of `original` and the clip's translation tracks.
  TruthFn truth;
  std::vector<std::optional<TranslationTrack>> translation_tracks;  // [joint]
  // The source: largest key count and largest angle from the first frame (degrees), [joint].
  std::vector<double> keys, motion_deg;
  // Foot contact (foot_skating.h): the feet, the floor (clip units), and the
  // reference's contacts [foot]; the clip's metres per unit and its description.
  std::vector<std::size_t> feet;
  double floor = 0.0, metres_per_unit = 1.0;
  std::string unit;
  std::vector<FootContact> foot_ref;
  std::optional<CycleFrames> cycle;  // with options.loop (eval/seam.h)
};

// Time of sample m < reference.samples: frame k = m / per_frame, then the fraction
// (m mod per_frame) / per_frame of the interval to frame k + 1.
double sample_time(const ClipReference& reference, std::size_t m);

// Builds the reference of `clip` (validated first). Errors name the clip id.
Result<ClipReference> prepare_reference(const Clip& clip, const std::string& clip_id,
                                        const ClipEvalOptions& options);

// How many times prepare_reference has run in this process (from any
// thread): eval builds one per clip and shares it, read-only, among every method and
// spacing and the worker threads running them; tests hold it to that.
std::size_t references_prepared();

// Rows of one method for every keep_every × joint, then End Site (with fk only); none
// for the spacings skipped_spacings() names. Only the reference's metrics are computed. Errors name the clip, the joint and the method.
Result<std::vector<ErrorRow>> evaluate_method(const ClipReference& reference, const std::string& method,
                                              const ClipEvalOptions& options);

// The angle error (degrees) of every joint at every sample, rebuilt by `method`
// from every keep_every-th frame: eval --per-frame.
struct PerFrameErrors {
  std::vector<double> times;              // seconds, per sample
  std::vector<std::vector<double>> angle;  // [joint][sample], degrees
};
Result<PerFrameErrors> per_frame_errors(const ClipReference& reference, const std::string& method, int keep_every);

// Rows for every method × keep_every × joint, then End Site, in that order: the
// two steps above. The first error ends it.
Result<std::vector<ErrorRow>> evaluate_clip(const Clip& clip, const std::string& clip_id,
                                            const ClipEvalOptions& options);

}  // namespace rotinterp
