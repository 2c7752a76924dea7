// The one camera all panels share, framed from the bounds of everything drawn,
// and the ground grid under it; the camera of a trail inset. World is Y-up
// (BVH's and assimp's convention).
#pragma once

#include "rotinterp/core/rotation.h"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <vector>

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

// How many pixels `radius` (world units) at the camera's target spans in a
// viewport `viewport_height` pixels high.
double pixels_at_target(const Camera& camera, double radius, int viewport_height);

// A trail sample as a point of the unit sphere: v normalized, or zero where v is
// zero or not finite.
Vec3 unit_or_zero(const Vec3& v);

// The view of a trail inset (square) onto the unit sphere, and the zoom its tubes
// and markers scale by so that they keep their size on screen.
struct TrailView {
  Camera camera;
  double zoom = 1.0;  // tan(half field) / tan(18°): 1 when the whole sphere is seen
};

// The plane that best fits the `reference` samples (unit_or_zero of each; least
// squares: through their centroid, normal to the covariance's smallest
// eigenvector), its normal on the side of the centroid — when they lie near a
// plane: their variance across it (the smallest eigenvalue) at most
// kTrailMaxFlatness of the middle one. Nothing for a dot (largest standard
// deviation under kTrailMinSpread), a curve that fills the sphere, or one that
// hardly bends (the middle eigenvalue under kTrailMinBend of the largest: a
// circular arc shorter than about 50°, which its mean direction shows straight
// and whole, as it is on the sphere).
constexpr double kTrailMaxFlatness = 0.2;
constexpr double kTrailMinSpread = 0.005;
constexpr double kTrailMinBend = 0.01;
struct TrailPlane {
  Vec3 normal;
  Vec3 centroid;
};
std::optional<TrailPlane> trail_plane(const std::vector<Vec3>& reference);

// Where there is a trail_plane(reference), looks at its centroid along its normal,
// so that a planar curve (a hinge's arc) is seen face on, not edge on (a plane
// through the centre is seen from the scene camera's side). Else looks at the
// sphere's centre from the mean direction of the samples, so that the curve faces
// the viewer; from `scene_view`'s azimuth and elevation (at least 20°) where that
// mean is shorter than 0.2. The field holds
// the sample of either curve farthest from the view axis with a margin: half-angle
// at most 18° (the whole sphere), at least 1.5°. `reference` is not empty.
TrailView trail_view(const std::vector<Vec3>& reference, const std::vector<Vec3>& method, const ViewAngles& scene_view);

}  // namespace rotinterp::render
