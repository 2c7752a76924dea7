// Joint axes as RGB triads (axes.h): when they are drawn, how long, and their capsules.
#include "rotinterp/render/axes.h"

#include <algorithm>
#include <string>
#include <vector>

namespace rotinterp::render {

namespace {
constexpr double kCoincident = 1e-6;     // units: joints closer than this are one point
constexpr double kFigureFraction = 0.1;  // of the figure's largest side
constexpr double kPointFigureLength = 0.4;  // units, in the unit cube a point is framed in
constexpr double kBoneRadii = 4.0;       // the least length, in bone radii
constexpr double kThickness = 0.05;      // radius over length
}  // namespace

Result<AxesMode> parse_axes(std::string_view name) {
  if (name == "auto") return AxesMode::automatic;
  if (name == "on") return AxesMode::on;
  if (name == "off") return AxesMode::off;
  return make_error("--axes '" + std::string(name) + "' is not auto, on or off");
}

bool joints_coincide(const Clip& clip) {
  if (clip.skeleton.joints.empty()) return false;
  auto spread = [&](const WorldPose& pose) {
    Bounds b;
    for (const Vec3& p : pose.position) b.extend(p);
    return b.empty() ? 0.0 : b.size().maxCoeff();
  };
  if (spread(rest_pose(clip.skeleton)) > kCoincident) return false;
  std::vector<Quat> rotation;
  std::vector<Vec3> translation;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    rotation.push_back(clip.rotations[j].keys.empty() ? clip.skeleton.joints[j].rest_rotation : clip.rotations[j].keys.front());
    translation.push_back(clip.translations[j] && !clip.translations[j]->keys.empty() ? clip.translations[j]->keys.front()
                                                                                    : clip.skeleton.joints[j].offset);
  }
  WorldPose first;
  forward_kinematics(clip.skeleton, rotation, translation, first);
  return spread(first) <= kCoincident;
}

bool draws_axes(AxesMode mode, const Clip& clip) {
  if (mode != AxesMode::automatic) return mode == AxesMode::on;
  return clip.skeleton.joints.size() == 1 || joints_coincide(clip);
}

double axes_length(const Bounds& box, double bone_radius) {
  const double side = box.empty() ? 0.0 : box.size().maxCoeff();
  return std::max(side > 0.0 ? kFigureFraction * side : kPointFigureLength, kBoneRadii * bone_radius);
}

void add_axes(const Skeleton& skeleton, const WorldPose& pose, double length, Batch& batch) {
  if (pose.position.size() != skeleton.joints.size() || pose.rotation.size() != skeleton.joints.size()) return;
  for (std::size_t j = 0; j < pose.position.size(); ++j) {
    const Mat3 r = pose.rotation[j].toRotationMatrix();
    for (int axis = 0; axis < 3; ++axis)
      batch.cylinder(pose.position[j], pose.position[j] + length * r.col(axis), kThickness * length, 0.0,
                     kAxisColours[axis], 1.0f);
  }
}

}  // namespace rotinterp::render
