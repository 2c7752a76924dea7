// What the camera frames over the frames drawn: one fixed box, or boxes that follow
// the root or a focus joint (private to render/).
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

// What the camera frames over frames first…last (poses[f - first]): one box
// (fixed), or a box per frame that moves with the followed point, smoothed over
// `smoothing` seconds (follow). Following the root the box moves horizontally
// only (the ground stays put); following a focus joint it moves in 3-D.
struct Views {
  Bounds fixed;
  std::vector<Bounds> moving;  // [f - first]; empty when fixed
};

Views camera_views(const RebuiltClip& rebuild, const std::vector<WorldPose>& poses, std::size_t first, int followed,
                   const std::vector<bool>& limb, bool follow, double smoothing, double min_side);

}  // namespace rotinterp::render
