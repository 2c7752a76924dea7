// geometry: the unit meshes, their placed instances and the line lists, on the CPU.
#include "rotinterp/render/geometry.h"

#include "rotinterp/render/axes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rotinterp::render {

namespace {

constexpr Colour kGhostColour = {0.84f, 0.87f, 0.92f};
constexpr float kGhostAlpha = 0.33f;
constexpr Colour kKeyMarker = {0.96f, 0.96f, 0.96f};
constexpr float kGridLine[4] = {0.30f, 0.32f, 0.35f, 1.0f};
constexpr float kSphereWire[4] = {0.30f, 0.32f, 0.36f, 1.0f};

Instance make_instance(const Eigen::Matrix4d& model, const Colour& colour, float alpha) {
  Instance in;
  const Eigen::Matrix4f f = model.cast<float>();
  std::memcpy(in.model, f.data(), sizeof in.model);  // Eigen is column-major, like GL
  in.colour[0] = colour[0];
  in.colour[1] = colour[1];
  in.colour[2] = colour[2];
  in.colour[3] = alpha;
  return in;
}

// `colour` mixed towards the inset background: f = 1 keeps it, f = 0 is the background.
Colour faded(const Colour& colour, float f) {
  return {kInsetBackground[0] + f * (colour[0] - kInsetBackground[0]), kInsetBackground[1] + f * (colour[1] - kInsetBackground[1]),
          kInsetBackground[2] + f * (colour[2] - kInsetBackground[2])};
}

bool pose_usable(const WorldPose& pose, const Skeleton& skeleton) {
  return pose.position.size() == skeleton.joints.size() && !pose.position.empty();
}

void push_line(LineList& lines, const Vec3& a, const Vec3& b, const float rgba[4]) {
  for (const Vec3* p : {&a, &b})
    lines.insert(lines.end(), {static_cast<float>(p->x()), static_cast<float>(p->y()), static_cast<float>(p->z()),
                               rgba[0], rgba[1], rgba[2], rgba[3]});
}

}  // namespace

MeshData cylinder_mesh(int sides) {
  MeshData m;
  for (int i = 0; i <= sides; ++i) {
    const double a = kTwoPi * i / sides;
    const float c = static_cast<float>(std::cos(a)), s = static_cast<float>(std::sin(a));
    for (float z : {0.0f, 1.0f}) m.vertices.insert(m.vertices.end(), {c, s, z, c, s, 0.0f});
  }
  for (unsigned i = 0; i < static_cast<unsigned>(sides); ++i) {
    const unsigned a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
  }
  return m;
}

MeshData sphere_mesh(int slices, int stacks) {
  MeshData m;
  for (int j = 0; j <= stacks; ++j) {
    const double phi = kPi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double theta = kTwoPi * i / slices;
      const float x = static_cast<float>(std::sin(phi) * std::cos(theta));
      const float y = static_cast<float>(std::cos(phi));
      const float z = static_cast<float>(std::sin(phi) * std::sin(theta));
      m.vertices.insert(m.vertices.end(), {x, y, z, x, y, z});
    }
  }
  const unsigned row = static_cast<unsigned>(slices + 1);
  for (unsigned j = 0; j < static_cast<unsigned>(stacks); ++j)
    for (unsigned i = 0; i < static_cast<unsigned>(slices); ++i) {
      const unsigned a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
    }
  return m;
}

void Batch::clear() {
  cylinders.clear();
  spheres.clear();
}

void Batch::sphere(const Vec3& p, double radius, const Colour& colour, float alpha) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = Mat3::Identity() * radius;
  m.block<3, 1>(0, 3) = p;
  spheres.push_back(make_instance(m, colour, alpha));
}

void Batch::cylinder(const Vec3& a, const Vec3& b, double radius, double min_length, const Colour& colour, float alpha) {
  const Vec3 d = b - a;
  const double length = d.norm();
  if (!(length > min_length)) return;
  const Mat3 r = Quat::FromTwoVectors(Vec3::UnitZ(), d / length).toRotationMatrix();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = r * Eigen::Vector3d(radius, radius, length).asDiagonal();
  m.block<3, 1>(0, 3) = a;
  cylinders.push_back(make_instance(m, colour, alpha));
}

void add_pose(const Skeleton& skeleton, const WorldPose& pose, double radius, const Colour& colour, float alpha,
              Batch& batch, const std::vector<Colour>& joint_colours, const std::vector<bool>& thin) {
  if (!pose_usable(pose, skeleton)) return;
  const bool per_joint = joint_colours.size() == skeleton.joints.size();
  const bool thinning = thin.size() == skeleton.joints.size();
  auto bone_radius = [&](std::size_t j) { return thinning && thin[j] ? kThinBone * radius : radius; };
  auto bone_colour = [&](std::size_t j) -> const Colour& { return per_joint ? joint_colours[j] : colour; };
  const double min_length = radius * 1e-3;
  for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
    const int p = skeleton.joints[j].parent;
    const auto turner = p >= 0 ? static_cast<std::size_t>(p) : j;
    if (p >= 0)
      batch.cylinder(pose.position[turner], pose.position[j], bone_radius(turner), min_length, bone_colour(turner), alpha);
    batch.sphere(pose.position[j], thinning && thin[j] ? kThinBone * radius : radius, bone_colour(turner), alpha);
  }
  if (pose.end_site_position.size() != skeleton.end_sites.size()) return;
  for (std::size_t e = 0; e < skeleton.end_sites.size(); ++e) {
    const auto parent = static_cast<std::size_t>(skeleton.end_sites[e].parent);
    const Vec3& b = pose.end_site_position[e];
    batch.cylinder(pose.position[parent], b, bone_radius(parent), min_length, bone_colour(parent), alpha);
    batch.sphere(b, bone_radius(parent), bone_colour(parent), alpha);
  }
}

void add_curve(const std::vector<Vec3>& points, std::size_t stride, double radius, const Colour& colour, float alpha,
               Batch& batch, const std::vector<float>& fade) {
  if (points.empty()) return;
  const bool fading = fade.size() == points.size();
  auto f = [&](std::size_t k) { return fading ? std::clamp(fade[k], 0.0f, 1.0f) : 1.0f; };
  std::size_t previous = 0;
  batch.sphere(unit_or_zero(points[0]), radius, faded(colour, f(0)), alpha * f(0));
  for (std::size_t i = stride; ; i += stride) {
    const std::size_t k = std::min(i, points.size() - 1);
    if (k == previous) break;
    const Vec3 a = unit_or_zero(points[previous]), b = unit_or_zero(points[k]);
    const float w = std::max(f(previous), f(k));
    batch.cylinder(a, b, radius, 1e-6, faded(colour, w), alpha * w);
    batch.sphere(b, radius, faded(colour, f(k)), alpha * f(k));
    previous = k;
  }
}

void panel_figure(const Scene& scene, const Panel& panel, Batch& solid, Batch& translucent) {
  solid.clear();
  const double axes = axes_length(panel.view ? *panel.view : scene.bounds, scene.bone_radius);
  add_pose(scene.skeleton, panel.pose, scene.bone_radius, panel.colour, 1.0f, solid, panel.joint_colours, scene.thin);
  if (scene.axes) add_axes(scene.skeleton, panel.pose, axes, solid);
  for (const Figure& figure : panel.figures) {
    add_pose(scene.skeleton, figure.pose, kOverlayBone * scene.bone_radius, figure.colour, 1.0f, solid, {}, scene.thin);
    if (scene.axes) add_axes(scene.skeleton, figure.pose, axes, solid);
  }
  translucent.clear();
  add_pose(scene.skeleton, panel.ghost, scene.bone_radius * 1.02, kGhostColour, kGhostAlpha, translucent, {}, scene.thin);
}

void trail_figure(const Trail& trail, const Colour& colour, double zoom, Batch& solid, Batch& translucent) {
  const std::size_t n = trail.reference.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + kMaxTrailSegments - 1) / kMaxTrailSegments);
  solid.clear();
  add_curve(trail.method, stride, zoom * kTrailMethodRadius, colour, 1.0f, solid, trail.fade);
  const bool fading = trail.fade.size() == n;
  if (trail.keys.size() <= kMaxKeyMarkers)
    for (std::size_t k : trail.keys)
      if (k < trail.method.size())
        solid.sphere(unit_or_zero(trail.method[k]), zoom * kTrailKeyRadius,
                     fading ? faded(kKeyMarker, std::clamp(trail.fade[k], 0.0f, 1.0f)) : kKeyMarker, 1.0f);
  if (trail.current < trail.method.size())
    solid.sphere(unit_or_zero(trail.method[trail.current]), zoom * kTrailCurrentRadius, colour, 1.0f);
  translucent.clear();
  add_curve(trail.reference, stride, zoom * kTrailReferenceRadius, kGhostColour, kGhostAlpha, translucent, trail.fade);
  if (trail.current < n)
    translucent.sphere(unit_or_zero(trail.reference[trail.current]), zoom * kTrailCurrentRadius * 1.25, kGhostColour,
                       kGhostAlpha);
}

LineList grid_lines(const Bounds& bounds) {
  LineList lines;
  const GroundGrid g = ground_grid(bounds);
  const auto nx = static_cast<long>(std::llround((g.x1 - g.x0) / g.step));
  const auto nz = static_cast<long>(std::llround((g.z1 - g.z0) / g.step));
  for (long i = 0; i <= nx; ++i) {
    const double x = g.x0 + static_cast<double>(i) * g.step;
    push_line(lines, Vec3(x, g.y, g.z0), Vec3(x, g.y, g.z1), kGridLine);
  }
  for (long i = 0; i <= nz; ++i) {
    const double z = g.z0 + static_cast<double>(i) * g.step;
    push_line(lines, Vec3(g.x0, g.y, z), Vec3(g.x1, g.y, z), kGridLine);
  }
  return lines;
}

LineList sphere_wireframe() {
  LineList lines;
  constexpr int kSegments = 48;  // per parallel, and per meridian from pole to pole
  auto point = [](double lat, double lon) {
    return Vec3(std::cos(lat) * std::sin(lon), std::sin(lat), std::cos(lat) * std::cos(lon));
  };
  for (int p = -2; p <= 2; ++p)
    for (int s = 0; s < kSegments; ++s)
      push_line(lines, point(p * kPi / 6, kTwoPi * s / kSegments), point(p * kPi / 6, kTwoPi * (s + 1) / kSegments),
                kSphereWire);
  for (int m = 0; m < 6; ++m)
    for (int s = 0; s < kSegments; ++s)
      push_line(lines, point(-kPi / 2 + kPi * s / kSegments, m * kPi / 6),
                point(-kPi / 2 + kPi * (s + 1) / kSegments, m * kPi / 6), kSphereWire);
  return lines;
}

double scene_bone_radius(const Skeleton& skeleton, const Bounds& bounds) {
  std::vector<double> lengths;
  for (const Joint& j : skeleton.joints)
    if (j.parent >= 0 && j.offset.norm() > 0.0) lengths.push_back(j.offset.norm());
  for (const EndSite& e : skeleton.end_sites)
    if (e.offset.norm() > 0.0) lengths.push_back(e.offset.norm());
  const double diagonal = bounds.empty() ? 1.0 : std::max(bounds.size().norm(), 1e-9);
  if (lengths.empty()) return 0.01 * diagonal;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  const double median = lengths[lengths.size() / 2];
  return std::clamp(0.1 * median, 0.004 * diagonal, 0.02 * diagonal);
}

}  // namespace rotinterp::render
