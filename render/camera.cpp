// camera: the shared camera framed from the bounds of all panels, and the trail inset's.
#include "rotinterp/render/camera.h"

#include <Eigen/Eigenvalues>

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

double pixels_at_target(const Camera& camera, double radius, int viewport_height) {
  return radius / ((camera.eye - camera.target).norm() * std::tan(0.5 * camera.fov_y)) * 0.5 * viewport_height;
}

Vec3 unit_or_zero(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 && std::isfinite(n) ? Vec3(v / n) : Vec3::Zero();
}

std::optional<TrailPlane> trail_plane(const std::vector<Vec3>& reference) {
  if (reference.size() < 3) return std::nullopt;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& d : reference) centroid += unit_or_zero(d);
  centroid /= static_cast<double>(reference.size());
  Mat3 covariance = Mat3::Zero();
  for (const Vec3& d : reference) {
    const Vec3 r = unit_or_zero(d) - centroid;
    covariance += r * r.transpose();
  }
  covariance /= static_cast<double>(reference.size());
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(covariance);  // eigenvalues ascending
  const Vec3 lambda = eigen.eigenvalues();
  if (eigen.info() != Eigen::Success || !lambda.allFinite()) return std::nullopt;
  if (lambda(2) < kTrailMinSpread * kTrailMinSpread) return std::nullopt;  // a dot
  if (lambda(0) > kTrailMaxFlatness * lambda(1)) return std::nullopt;      // fills the sphere
  if (lambda(1) < kTrailMinBend * lambda(2)) return std::nullopt;           // nearly straight: no face to show
  Vec3 normal = eigen.eigenvectors().col(0).normalized();
  if (normal.dot(centroid) < 0.0) normal = -normal;
  return TrailPlane{normal, centroid};
}

TrailView trail_view(const std::vector<Vec3>& reference, const std::vector<Vec3>& method, const ViewAngles& scene_view) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& d : reference) mean += unit_or_zero(d);
  mean /= static_cast<double>(reference.size());
  const double az = scene_view.azimuth_deg * kPi / 180.0;
  const double el = std::max(scene_view.elevation_deg, 20.0) * kPi / 180.0;
  const Vec3 scene_back(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  Vec3 toward, target = Vec3::Zero();
  if (const auto plane = trail_plane(reference)) {
    // A plane through the centre (a great circle) has no outer side: the scene's.
    const Vec3& n = plane->normal;
    toward = std::abs(n.dot(mean)) > 1e-3 || n.dot(scene_back) >= 0.0 ? n : Vec3(-n);
    target = plane->centroid;
  } else if (mean.norm() > 0.2) {
    toward = mean.normalized();
  } else {
    toward = scene_back;
  }
  TrailView view;
  Camera& camera = view.camera;
  camera.eye = target + 3.9 * toward;
  camera.target = target;
  camera.up = std::abs(toward.y()) < 0.95 ? Vec3::UnitY() : Vec3::UnitZ();
  // Tangent of the angle between the view axis and each sample, seen from the eye.
  double spread = 0.0;
  for (const std::vector<Vec3>* curve : {&reference, &method})
    for (const Vec3& d : *curve) {
      const Vec3 r = unit_or_zero(d) - target;
      spread = std::max(spread, (r - r.dot(toward) * toward).norm() / (3.9 - std::max(r.dot(toward), 0.0)));
    }
  const double max_half = 18.0 * kPi / 180.0;
  const double half = std::clamp(std::atan(1.25 * spread + 0.02), 1.5 * kPi / 180.0, max_half);
  view.zoom = std::tan(half) / std::tan(max_half);
  camera.fov_y = 2.0 * half;
  camera.aspect = 1.0;
  camera.near_plane = 0.8;  // the sphere lies 1.9…7.9 from an eye 3.9 from a target inside it
  camera.far_plane = 8.0;
  return view;
}

}  // namespace rotinterp::render
