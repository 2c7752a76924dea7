// What the camera frames over the frames drawn: the body (not a ground marker at the
// root), in one fixed box or in boxes that follow the pelvis or a focus joint
// (private to render/).
#pragma once

#include "rotinterp/clip/rebuild.h"
#include "rotinterp/render/camera.h"

#include <cstddef>
#include <vector>

namespace rotinterp::render {

// The fraction of frames a following view's box (and the error strip's scale)
// holds entirely: outliers — a reference pose in frame 0, a flip — do not shrink
// everything else.
inline constexpr double kRobustFraction = 0.98;

// The value below which `fraction` of `values` lie (nearest rank); 0 when empty.
double quantile(std::vector<double> values, double fraction);

// Joint `joint` and every joint below it.
std::vector<bool> subtree(const Skeleton& skeleton, int joint);

// The points of `pose` a view frames: every joint and End Site, or those of
// `limb` (subtree()) when it is not empty.
template <typename F>
void for_each_point(const Skeleton& skeleton, const WorldPose& pose, const std::vector<bool>& limb, F&& f) {
  for (std::size_t j = 0; j < pose.position.size(); ++j)
    if (limb.empty() || limb[j]) f(pose.position[j]);
  if (pose.end_site_position.size() != skeleton.end_sites.size()) return;
  for (std::size_t e = 0; e < skeleton.end_sites.size(); ++e)
    if (limb.empty() || limb[static_cast<std::size_t>(skeleton.end_sites[e].parent)]) f(pose.end_site_position[e]);
}

// The figure's body over the frames drawn. A root whose bone to a child stretches
// by more than kMarkerStretch of the figure's height is a ground marker (a joint
// left at the origin while the body travels, as in the Bandai Namco captures): it
// is not framed or followed, and its bones are drawn thin. The pelvis is the
// topmost joint kept with the most joints below it.
inline constexpr double kMarkerStretch = 0.25;
struct Body {
  std::vector<bool> marker;  // per joint
  std::vector<bool> kept;    // per joint: !marker
  int pelvis = 0;
};
Body find_body(const Skeleton& skeleton, const std::vector<WorldPose>& poses);

// What a camera frames: the points of `points` (for_each_point's limb), following
// joint `followed` — in 3-D when `vertical` (a focus joint), else horizontally
// only (the ground stays put) — smoothed over `smoothing` seconds, the box at
// least `min_side` on every side.
struct Framing {
  std::vector<bool> points;
  int followed = 0;
  bool vertical = false;
  double smoothing = 0.5;
  double min_side = 0.0;
};

// What the camera frames over frames first…last (poses[f - first]): one box
// (fixed), or a box per frame that moves with the followed point (follow).
struct Views {
  Bounds fixed;
  std::vector<Bounds> moving;  // [f - first]; empty when fixed
};

Views camera_views(const RebuiltClip& rebuild, const std::vector<WorldPose>& poses, std::size_t first,
                   const Framing& framing, bool follow);

}  // namespace rotinterp::render
