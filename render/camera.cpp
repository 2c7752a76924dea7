#include "rotinterp/render/camera.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rotinterp::render {

void Bounds::extend(const Vec3& p) {
  if (!p.allFinite()) return;
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

Eigen::Matrix4d Camera::view() const {
  const Vec3 f = (target - eye).normalized();
  const Vec3 s = f.cross(up).normalized();
  const Vec3 u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d Camera::projection() const {
  const double t = 1.0 / std::tan(0.5 * fov_y);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0;
  return m;
}

namespace {

// The box, grown to a unit cube where it is empty or flat in every direction.
Bounds usable(const Bounds& b) {
  if (b.empty()) {
    Bounds u;
    u.extend(Vec3::Constant(-0.5));
    u.extend(Vec3::Constant(0.5));
    return u;
  }
  const double extent = b.size().maxCoeff();
  if (extent > 0.0) return b;
  Bounds u;
  u.extend(b.center() - Vec3::Constant(0.5));
  u.extend(b.center() + Vec3::Constant(0.5));
  return u;
}

}  // namespace

Camera frame_bounds(const Bounds& bounds, double aspect, const ViewAngles& angles) {
  const Bounds b = usable(bounds);
  const double az = angles.azimuth_deg * kPi / 180.0;
  const double el = angles.elevation_deg * kPi / 180.0;
  const Vec3 back(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));  // target → eye
  const Vec3 right = Vec3::UnitY().cross(back).normalized();
  const Vec3 up = back.cross(right);
  Camera cam;
  cam.fov_y = angles.fov_y_deg * kPi / 180.0;
  cam.aspect = aspect > 0.0 ? aspect : 1.0;
  const double tan_v = std::tan(0.5 * cam.fov_y) * (1.0 - angles.margin);
  const double tan_h = tan_v * cam.aspect;
  const Vec3 c = b.center();
  // Camera at c + D·back; a corner at (x, y, z) in (right, up, back) has depth D − z
  // and is inside the frustum when |x| ≤ tan_h (D − z) and |y| ≤ tan_v (D − z).
  double distance = 0.0;
  double radius = 0.0;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? b.max.x() : b.min.x(), (i & 2) ? b.max.y() : b.min.y(), (i & 4) ? b.max.z() : b.min.z());
    const Vec3 rel = corner - c;
    const double x = rel.dot(right), y = rel.dot(up), z = rel.dot(back);
    distance = std::max({distance, z + std::abs(x) / tan_h, z + std::abs(y) / tan_v});
    radius = std::max(radius, rel.norm());
  }
  cam.target = c;
  cam.eye = c + distance * back;
  cam.up = Vec3::UnitY();
  // The grid reaches one cell past the box: leave room behind, and a near plane
  // well in front of everything.
  cam.near_plane = std::max(distance - 2.0 * radius, 1e-3 * distance);
  cam.far_plane = distance + 3.0 * radius;
  return cam;
}

GroundGrid ground_grid(const Bounds& bounds) {
  const Bounds b = usable(bounds);
  const double extent = std::max({b.size().x(), b.size().z(), 1e-9});
  const double raw = extent / 8.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= raw) {
      step = m * decade;
      break;
    }
  GroundGrid g;
  g.y = b.min.y();
  g.step = step;
  g.x0 = (std::floor(b.min.x() / step) - 1.0) * step;
  g.x1 = (std::ceil(b.max.x() / step) + 1.0) * step;
  g.z0 = (std::floor(b.min.z() / step) - 1.0) * step;
  g.z1 = (std::ceil(b.max.z() / step) + 1.0) * step;
  return g;
}

}  // namespace rotinterp::render
