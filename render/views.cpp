// The camera's boxes over the frames drawn: the body found, fixed or following the smoothed pelvis or a focus joint.
#include "views.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

Body find_body(const Skeleton& skeleton, const std::vector<WorldPose>& poses) {
  const std::size_t joints = skeleton.joints.size();
  Body body;
  body.marker.assign(joints, false);
  const double height = skeleton_height(rest_pose(skeleton));
  std::vector<double> shortest(joints, std::numeric_limits<double>::infinity()), longest(joints, 0.0);
  for (const WorldPose& pose : poses) {
    if (pose.position.size() != joints) continue;
    for (std::size_t j = 0; j < joints; ++j) {
      const int p = skeleton.joints[j].parent;
      if (p < 0 || skeleton.joints[static_cast<std::size_t>(p)].parent >= 0) continue;  // bones from a root
      const double length = (pose.position[j] - pose.position[static_cast<std::size_t>(p)]).norm();
      if (!std::isfinite(length)) continue;
      shortest[j] = std::min(shortest[j], length);
      longest[j] = std::max(longest[j], length);
    }
  }
  for (std::size_t j = 0; j < joints; ++j)
    if (longest[j] - shortest[j] > kMarkerStretch * height)
      body.marker[static_cast<std::size_t>(skeleton.joints[j].parent)] = true;
  // Joints below each joint, children after parents: count them back to front.
  std::vector<std::size_t> below(joints, 0);
  for (std::size_t j = joints; j-- > 0;)
    if (const int p = skeleton.joints[j].parent; p >= 0) below[static_cast<std::size_t>(p)] += below[j] + 1;
  int best = -1;
  for (std::size_t j = 0; j < joints; ++j) {
    const int p = skeleton.joints[j].parent;
    const bool top = !body.marker[j] && (p < 0 || body.marker[static_cast<std::size_t>(p)]);
    if (top && (best < 0 || below[j] > below[static_cast<std::size_t>(best)])) best = static_cast<int>(j);
  }
  body.pelvis = std::max(best, 0);
  body.kept.resize(joints);
  for (std::size_t j = 0; j < joints; ++j) body.kept[j] = !body.marker[j];
  return body;
}

Views camera_views(const RebuiltClip& rebuild, const std::vector<WorldPose>& poses, std::size_t first,
                   const Framing& framing, bool follow) {
  const Skeleton& skeleton = rebuild.skeleton();
  const std::vector<bool>& limb = framing.points;
  Views v;
  for (const WorldPose& pose : poses) for_each_point(skeleton, pose, limb, [&](const Vec3& p) { v.fixed.extend(p); });
  if (!follow || poses.empty()) return v;
  const double smoothing = framing.smoothing, min_side = framing.min_side;
  const auto followed = static_cast<std::size_t>(framing.followed);
  const std::size_t n = poses.size();
  // The smoothing window in frames, from the mean frame spacing.
  const double span = rebuild.time(first + n - 1) - rebuild.time(first);
  const double spacing = n > 1 && span > 0.0 ? span / static_cast<double>(n - 1) : 1.0;
  const auto half = static_cast<std::size_t>(std::lround(smoothing / spacing));
  std::vector<Vec3> path(n), prefix(n + 1, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + poses[i].position[followed];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i >= half ? i - half : 0, hi = std::min(n - 1, i + half);
    path[i] = (prefix[hi + 1] - prefix[lo]) / static_cast<double>(hi - lo + 1);
    if (!framing.vertical) path[i].y() = 0.0;
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
