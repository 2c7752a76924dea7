// What the renderer draws, computed on the CPU without GL: the unit meshes
// (cylinder, sphere), instances of them placed and coloured (bones, joints,
// trail tubes and markers), and line lists (ground grid, sphere wireframe).
// The renderer uploads these as they are.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/render/camera.h"
#include "rotinterp/render/renderer.h"

#include <vector>

namespace rotinterp::render {

// ---- unit meshes ---------------------------------------------------------------

struct MeshData {
  std::vector<float> vertices;    // x y z nx ny nz per vertex
  std::vector<unsigned> indices;  // triangles
};

// Radius 1 about +Z, from z = 0 to z = 1, open (joint spheres close it); `sides`
// quads around.
MeshData cylinder_mesh(int sides);

// Unit sphere about the origin, `slices` around +Y and `stacks` from pole to pole.
MeshData sphere_mesh(int slices, int stacks);

// ---- instances -----------------------------------------------------------------

// One placed copy of a unit mesh, laid out as the instance attributes read it.
struct Instance {
  float model[16];  // column-major
  float colour[4];   // linear RGB, alpha
};

// Instances of the cylinder and of the sphere, drawn together with one look.
struct Batch {
  std::vector<Instance> cylinders;
  std::vector<Instance> spheres;

  void clear();
  void sphere(const Vec3& p, double radius, const Colour& colour, float alpha);
  // A capsule's body from a to b; skipped when not longer than `min_length`.
  void cylinder(const Vec3& a, const Vec3& b, double radius, double min_length, const Colour& colour, float alpha);
};

// Capsule bones joint → parent and End Site → joint, and a sphere at every joint
// and End Site. Nothing when the pose's positions do not match the skeleton's
// joints; no End Sites when its End Site positions do not match. With
// `joint_colours` (one per joint) the colours are per bone as Panel::joint_colours
// says, else all `colour`. With `thin` (one per joint) the bones a joint marked
// there turns are kThinBone as thick, and its sphere too.
inline constexpr double kThinBone = 0.3;
void add_pose(const Skeleton& skeleton, const WorldPose& pose, double radius, const Colour& colour, float alpha,
              Batch& batch, const std::vector<Colour>& joint_colours = {}, const std::vector<bool>& thin = {});

// The colour trails fade to (the trail inset's background).
constexpr Colour kInsetBackground = {0.120f, 0.128f, 0.145f};

// A tube through `points` (every `stride`-th, and the last) put on the unit sphere
// (unit_or_zero), with a sphere at every point used. With `fade` (one per point,
// 0…1) each piece's colour is mixed towards kInsetBackground and its alpha scaled
// by its end's fade.
void add_curve(const std::vector<Vec3>& points, std::size_t stride, double radius, const Colour& colour, float alpha,
               Batch& batch, const std::vector<float>& fade = {});

// A panel's figure: its pose and its figures (each kOverlayBone as thick, so that
// the ghost shows around them) into `solid`, its ghost (pale, a little thicker)
// into `translucent`. Both batches are cleared first.
inline constexpr double kOverlayBone = 0.7;
void panel_figure(const Scene& scene, const Panel& panel, Batch& solid, Batch& translucent);

// Trail sizes on the unit sphere (sphere radii), before the inset's zoom.
constexpr float kTrailReferenceRadius = 0.034f;
constexpr float kTrailMethodRadius = 0.017f;
constexpr float kTrailKeyRadius = 0.036f;
constexpr float kTrailCurrentRadius = 0.065f;
constexpr std::size_t kMaxTrailSegments = 720;  // longer trails are drawn with a stride
constexpr std::size_t kMaxKeyMarkers = 64;      // more keys than this are not marked (clutter)

// A trail on the unit sphere, its sizes scaled by `zoom` (TrailView::zoom): the
// method's tube, key markers and current sample in `colour` into `solid`; the
// reference's tube and current sample as a ghost into `translucent`. Both
// batches are cleared first.
void trail_figure(const Trail& trail, const Colour& colour, double zoom, Batch& solid, Batch& translucent);

// ---- line lists ----------------------------------------------------------------

// Line segments as x y z r g b a per end, two ends a segment.
using LineList = std::vector<float>;

// The ground grid (ground_grid(bounds)), in world space.
LineList grid_lines(const Bounds& bounds);

// The unit sphere's wireframe: parallels and meridians every 30°.
LineList sphere_wireframe();

}  // namespace rotinterp::render
