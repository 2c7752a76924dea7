// Each joint's axes as a small RGB triad (x red, y green, z blue) at its world
// orientation: a bone drawn as a line hides twist about its own axis, and a
// figure whose joints coincide (or a one-joint clip) draws as a dot without them.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/render/camera.h"
#include "rotinterp/render/geometry.h"

#include <string_view>

namespace rotinterp::render {

// When render draws the triads.
enum class AxesMode {
  automatic,  // when the clip has one joint or all its joints lie at one point (axes_by_default)
  on,
  off,
};
Result<AxesMode> parse_axes(std::string_view name);  // "auto", "on" or "off"

constexpr Colour kAxisColours[3] = {{0.92f, 0.16f, 0.14f}, {0.18f, 0.80f, 0.22f}, {0.20f, 0.36f, 0.98f}};

// Whether every joint lies within 1e-6 units of one point, at rest and in the
// first frame (a reader that lost the offsets; a clip of objects that turn in place).
bool joints_coincide(const Clip& clip);

// Whether `mode` draws the triads for `clip`: on, or automatic with one joint or
// joints that coincide.
bool draws_axes(AxesMode mode, const Clip& clip);

// A triad's length where the camera frames `box` (the scene's bounds, or a panel's
// view): 0.1 of its largest side; for a box of one point, which the camera frames
// as a unit cube, 0.4 units; at least 4 bone radii, so the joint's sphere does not
// hide it.
double axes_length(const Bounds& box, double bone_radius);

// The triad of every joint of `pose` (positions and world rotations), each axis a
// capsule body `length` long and 0.05 × `length` thick, into `batch`. Nothing
// when the pose does not match the skeleton.
void add_axes(const Skeleton& skeleton, const WorldPose& pose, double length, Batch& batch);

}  // namespace rotinterp::render
