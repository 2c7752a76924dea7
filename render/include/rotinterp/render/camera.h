// The one camera all panels share, framed from the bounds of everything drawn,
// and the ground grid under it. World is Y-up (BVH's and assimp's convention).
#pragma once

#include "rotinterp/core/rotation.h"

#include <Eigen/Core>

#include <limits>

namespace rotinterp::render {

// An axis-aligned box; empty until a point is added.
struct Bounds {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p);  // non-finite points are ignored
  bool empty() const { return !(min.x() <= max.x()); }
  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 size() const { return max - min; }
};

// Where the camera looks from. Defaults: a three-quarter view from the front
// (+Z) and right (+X), slightly from above.
struct ViewAngles {
  double azimuth_deg = 30.0;    // about +Y, from +Z towards +X
  double elevation_deg = 18.0;  // above the horizontal
  double fov_y_deg = 30.0;      // vertical field of view
  double margin = 0.06;         // fraction of the half-field kept free around the box
};

// A perspective camera (OpenGL conventions: right-handed eye space looking down −Z,
// clip depth −1…1).
struct Camera {
  Vec3 eye = Vec3(0, 0, 1);
  Vec3 target = Vec3::Zero();
  Vec3 up = Vec3::UnitY();
  double fov_y = 0.5;  // radians
  double aspect = 1.0; // width / height
  double near_plane = 0.01;
  double far_plane = 100.0;

  Eigen::Matrix4d view() const;
  Eigen::Matrix4d projection() const;
};

// The closest camera at `angles` that sees the whole box (all eight corners) in a
// viewport of `aspect` (width / height). An empty or degenerate box is grown to a
// unit cube around its centre (or the origin).
Camera frame_bounds(const Bounds& bounds, double aspect, const ViewAngles& angles = {});

// Lines on the ground plane y = bounds.min.y: spacing a 1-2-5 step giving about
// eight cells across the larger horizontal extent, covering the box plus one cell.
struct GroundGrid {
  double y = 0.0;
  double step = 1.0;
  double x0 = 0.0, x1 = 0.0, z0 = 0.0, z1 = 0.0;
};
GroundGrid ground_grid(const Bounds& bounds);

}  // namespace rotinterp::render
