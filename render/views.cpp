// The camera's boxes over the frames drawn: fixed, or following the smoothed root or a focus joint.
#include "views.h"

#include <algorithm>
#include <cmath>

namespace rotinterp::render {

// The value below which `fraction` of `values` lie (nearest rank); 0 when empty.
double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size()))) - 1;
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(std::min(k, values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

// Joint `joint` and every joint below it.
std::vector<bool> subtree(const Skeleton& skeleton, int joint) {
  std::vector<bool> in(skeleton.joints.size(), false);
  for (std::size_t j = 0; j < in.size(); ++j)
    for (int k = static_cast<int>(j); k >= 0; k = skeleton.joints[static_cast<std::size_t>(k)].parent)
      if (k == joint) {
        in[j] = true;
        break;
      }
  return in;
}

Views camera_views(const RebuiltClip& rebuild, const std::vector<WorldPose>& poses, std::size_t first, int followed,
                   const std::vector<bool>& limb, bool follow, double smoothing, double min_side) {
  const Skeleton& skeleton = rebuild.skeleton();
  Views v;
  for (const WorldPose& pose : poses) for_each_point(skeleton, pose, limb, [&](const Vec3& p) { v.fixed.extend(p); });
  if (!follow || poses.empty()) return v;
  const bool focus = !limb.empty();
  const std::size_t n = poses.size();
  // The smoothing window in frames, from the mean frame spacing.
  const double span = rebuild.time(first + n - 1) - rebuild.time(first);
  const double spacing = n > 1 && span > 0.0 ? span / static_cast<double>(n - 1) : 1.0;
  const auto half = static_cast<std::size_t>(std::lround(smoothing / spacing));
  std::vector<Vec3> path(n), prefix(n + 1, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + poses[i].position[static_cast<std::size_t>(followed)];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i >= half ? i - half : 0, hi = std::min(n - 1, i + half);
    path[i] = (prefix[hi + 1] - prefix[lo]) / static_cast<double>(hi - lo + 1);
    if (!focus) path[i].y() = 0.0;
  }
  // Each side of the box: where that side of the figure's own box lies, relative
  // to the path, in all but the most outlying frames.
  std::vector<double> sides[6];
  for (std::size_t i = 0; i < n; ++i) {
    Bounds b;
    for_each_point(skeleton, poses[i], limb, [&](const Vec3& p) { b.extend(p - path[i]); });
    if (b.empty()) continue;
    for (int a = 0; a < 3; ++a) {
      sides[a].push_back(-b.min(a));
      sides[3 + a].push_back(b.max(a));
    }
  }
  if (sides[0].empty()) return v;
  Bounds relative;
  for (int a = 0; a < 3; ++a) {
    relative.min(a) = -quantile(sides[a], kRobustFraction);
    relative.max(a) = quantile(sides[3 + a], kRobustFraction);
  }
  const Vec3 grow = (Vec3::Constant(min_side) - relative.size()).cwiseMax(0.0) * 0.5;
  relative.min -= grow;
  relative.max += grow;
  v.moving.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    v.moving[i].extend(relative.min + path[i]);
    v.moving[i].extend(relative.max + path[i]);
  }
  return v;
}

}  // namespace rotinterp::render
