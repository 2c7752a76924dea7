// Skeleton and Clip: their validate() rules, times and frame count, the rest pose and its size.
#include "rotinterp/clip/clip.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace rotinterp {

int Skeleton::find(std::string_view name) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

Status Skeleton::validate() const {
  if (joints.empty()) return make_error("skeleton has no joints");
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const Joint& j = joints[i];
    if (j.name.empty()) return make_error("joint " + std::to_string(i) + " has no name");
    if (!names.insert(j.name).second) return make_error("joint name '" + j.name + "' is used twice");
    if (j.parent >= static_cast<int>(i) || j.parent < -1)
      return make_error("joint '" + j.name + "' does not come after its parent");
    if (!j.offset.allFinite()) return make_error("joint '" + j.name + "' has a non-finite offset");
    if (!j.rest_rotation.coeffs().allFinite() || std::abs(j.rest_rotation.norm() - 1.0) > 1e-9)
      return make_error("joint '" + j.name + "' has a rest rotation that is not a unit quaternion");
  }
  for (const EndSite& e : end_sites) {
    if (e.parent < 0 || e.parent >= static_cast<int>(joints.size()))
      return make_error("End Site '" + e.name + "' has no valid joint");
    if (!e.offset.allFinite()) return make_error("End Site '" + e.name + "' has a non-finite offset");
  }
  return Ok{};
}

Clip Clip::without_tracks() const {
  Clip c;
  c.name = name;
  c.skeleton = skeleton;
  c.unit = unit;
  c.source_format = source_format;
  c.source_meshes = source_meshes;
  c.source_record = rebuilt(source_record);
  return c;
}

Status Clip::validate() const {
  if (Status s = skeleton.validate(); !s) return s;
  const std::size_t n = skeleton.joints.size();
  if (rotations.size() != n) return make_error("clip has " + std::to_string(rotations.size()) +
                                               " rotation tracks for " + std::to_string(n) + " joints");
  if (translations.size() != n) return make_error("clip has " + std::to_string(translations.size()) +
                                                  " translation entries for " + std::to_string(n) + " joints");
  for (std::size_t i = 0; i < n; ++i) {
    if (Status s = rotations[i].validate(); !s)
      return s.failure("joint '" + skeleton.joints[i].name + "': ");
    if (translations[i])
      if (Status s = translations[i]->validate(); !s)
        return s.failure("joint '" + skeleton.joints[i].name + "': ");
  }
  if (!std::isfinite(frame_time) || frame_time < 0.0) return make_error("clip frame time is not a positive number");
  return Ok{};
}

double Clip::start_time() const {
  double t = INFINITY;
  for (const auto& r : rotations)
    if (!r.times.empty()) t = std::min(t, r.times.front());
  for (const auto& tr : translations)
    if (tr && !tr->times.empty()) t = std::min(t, tr->times.front());
  return std::isfinite(t) ? t : 0.0;
}

double Clip::end_time() const {
  double t = -INFINITY;
  for (const auto& r : rotations)
    if (!r.times.empty()) t = std::max(t, r.times.back());
  for (const auto& tr : translations)
    if (tr && !tr->times.empty()) t = std::max(t, tr->times.back());
  return std::isfinite(t) ? t : 0.0;
}

std::size_t Clip::frame_count() const {
  if (frame_time > 0.0) return static_cast<std::size_t>(std::llround((end_time() - start_time()) / frame_time)) + 1;
  std::size_t n = 0;
  for (const auto& r : rotations) n = std::max(n, r.times.size());
  for (const auto& tr : translations)
    if (tr) n = std::max(n, tr->times.size());
  return n;
}

void forward_kinematics(const Skeleton& skeleton, const std::vector<Quat>& local_rotation,
                        const std::vector<Vec3>& local_translation, WorldPose& out) {
  const std::size_t n = skeleton.joints.size();
  ROTINTERP_ASSERT(local_rotation.size() == n && local_translation.size() == n);
  out.rotation.resize(n);
  out.position.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int p = skeleton.joints[i].parent;
    if (p < 0) {
      out.rotation[i] = local_rotation[i];
      out.position[i] = local_translation[i];
    } else {
      out.rotation[i] = out.rotation[p] * local_rotation[i];
      out.position[i] = out.position[p] + out.rotation[p] * local_translation[i];
    }
  }
  out.end_site_position.resize(skeleton.end_sites.size());
  for (std::size_t e = 0; e < skeleton.end_sites.size(); ++e) {
    const EndSite& s = skeleton.end_sites[e];
    out.end_site_position[e] = out.position[s.parent] + out.rotation[s.parent] * s.offset;
  }
}

WorldPose rest_pose(const Skeleton& skeleton) {
  std::vector<Quat> r(skeleton.joints.size());
  std::vector<Vec3> t(skeleton.joints.size());
  for (std::size_t i = 0; i < skeleton.joints.size(); ++i) {
    r[i] = normalized_or_identity(skeleton.joints[i].rest_rotation);
    t[i] = skeleton.joints[i].offset;
  }
  WorldPose pose;
  forward_kinematics(skeleton, r, t, pose);
  return pose;
}

double skeleton_height(const WorldPose& pose) {
  if (pose.position.empty() && pose.end_site_position.empty()) return 0.0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  auto grow = [&](const Vec3& p) {
    if (!p.allFinite()) return;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const Vec3& p : pose.position) grow(p);
  for (const Vec3& p : pose.end_site_position) grow(p);
  if (!(hi.x() >= lo.x())) return 0.0;
  return (hi - lo).maxCoeff();
}

double metres_per_unit(const Clip& clip) {
  const double m = clip.unit.metres_per_unit;
  return std::isfinite(m) && m > 0.0 ? m : 1.0;
}

double in_clip_units(const Clip& clip, double metres) { return metres / metres_per_unit(clip); }

}  // namespace rotinterp
