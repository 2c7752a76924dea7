// The frames of a clip: the one definition eval, render and resample share of
// where a clip's frames are, what the source's motion is at each of them, which
// frames are kept as keys, and which way each bone points.
//
// Frames. A clip with a frame time has frame_count() frames on the reader's
// timeline, t_k = start + k·frame_time, the last one clamped to the clip's end;
// the same frames lie on the exact rational grid start + k/rate (clip/sampling.h),
// which resample uses to meet another rate bit-exactly. A clip whose keys lie on no
// grid (frame_time 0) has the key times of its longest rotation track as frames.
//
// Values. A track's value at a frame is its key there — a key within kFrameSnap of
// a frame is that frame's key (readers' times differ from a frame grid by
// round-off, and float key times by more) — else the slerp of its two neighbouring
// keys (translations: linear), held constant outside its keys.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/track/sample.h"  // sample_rotations, sample_translations: "Values" above

#include <cstddef>
#include <optional>
#include <vector>

namespace rotinterp {

// A key this close to a frame, as a fraction of a frame, is that frame's key: wide
// enough for float32 key times over hours of frames, far from the next frame.
inline constexpr double kFrameSnap = 0.05;

struct FrameGrid {
  double start = 0.0;          // seconds: frame 0
  double frame_time = 0.0;     // seconds per frame as the source states it; 0 if none
  std::optional<Rate> rate;    // the exact rate behind frame_time (rate_from_frame_time)
  std::vector<double> times;   // t_k on the reader's timeline
  double snap = 0.0;           // seconds: kFrameSnap of a frame (of the mean spacing without a frame time)

  std::size_t size() const { return times.size(); }
  // Frame k on the exact grid, start + k/rate; times[k] for a clip without a rate.
  double exact_time(std::size_t k) const;
  // The frame `t` belongs to (within `snap` of it), if any.
  std::optional<std::size_t> frame_at(double t) const;
};

FrameGrid frame_grid(const Clip& clip);

// The exact frame rate of a clip's source (rate_from_frame_time(clip.frame_time)),
// or nothing for a clip without a frame time: frame_grid(clip).rate, without the grid.
std::optional<Rate> clip_rate(const Clip& clip);

// The source's motion at every frame of its grid, joint-major: what the methods are
// measured against and where their keys are taken.
struct DenseClip {
  FrameGrid grid;
  std::vector<std::vector<Quat>> rotation;     // [joint][frame]
  std::vector<std::vector<Vec3>> translation;  // [joint][frame]: the track, or the rest offset
};
DenseClip dense_clip(const Clip& clip);
// The same at the frames' exact times, start + k/rate (a BVH "Frame Time: 0.0333333" is
// 1/30 s): where resample puts frames and reduce keys them. A clip without a rate keeps
// its times.
DenseClip exact_dense_clip(const Clip& clip);

// Frame indices kept as keys when keeping every nth of `frames` frames:
// 0, n, 2n, … and always the last frame (frames − 1). n < 1 reads as 1; empty for
// 0 frames.
std::vector<std::size_t> keep_every_indices(std::size_t frames, std::size_t n);

// The keys a joint's curve is rebuilt from: its rotations at the frames
// `key_frames` (one per frame of `times`), sign-continuous.
RotationTrack decimated_track(const std::vector<double>& times, const std::vector<Quat>& rotations,
                              const std::vector<std::size_t>& key_frames);

// The bone axis of every joint, a unit vector in the joint's own frame: the
// direction to its farthest child (joint or End Site rest offset). A joint without
// a child of non-zero length continues its parent bone: its own offset carried into
// its frame by the inverse rest rotation. Falls back to +x when that is zero too.
std::vector<Vec3> bone_axes(const Skeleton& skeleton);

}  // namespace rotinterp
