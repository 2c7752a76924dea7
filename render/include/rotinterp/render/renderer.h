// The comparison renderer: panels of skeleton poses (a solid pose over a
// translucent ghost), a shared camera and ground grid, titles, and optionally a
// rotation trail on a unit sphere — drawn with OpenGL 3.3 core into multisampled
// framebuffer objects of any GLContext, read back into an Image.
//
// The renderer takes poses, not clips or interpolators: what to draw is decided
// by the caller (render/comparison.h builds panels from a clip and methods).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/render/camera.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/image.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::render {

using Colour = std::array<float, 3>;  // linear 0…1 RGB

// A curve of unit directions drawn on a unit sphere in a corner of the panel:
// the reference (translucent, like the ghost) and the method's (solid), seen from
// the reference's mean direction. Keys are marked when there are at most 64.
struct Trail {
  std::string label;                // drawn above the sphere, e.g. the joint name
  std::vector<Vec3> reference;      // unit vectors; non-unit ones are normalized
  std::vector<Vec3> method;         // same length as reference
  std::vector<std::size_t> keys;    // indices of key samples, marked on the method curve
  std::size_t current = 0;          // index of the panel's frame, marked on both curves
  // Per sample, 0…1: how strongly it is drawn (1 full colour; less fades it towards
  // the inset's background, e.g. with the distance in time from `current`). Empty:
  // every sample at 1. Otherwise the same length as reference.
  std::vector<float> fade;
};

// An error-over-time strip under a panel: the method's max and mean error per
// frame over a range of frames, a cursor at the panel's frame, keys ticked.
struct ErrorStrip {
  std::vector<float> max_deg;      // degrees, per frame of the range
  std::vector<float> mean_deg;     // same length
  double scale_deg = 1.0;          // the strip's top (shared by the panels of an image)
  std::size_t cursor = 0;          // index of the panel's frame
  std::vector<std::size_t> keys;   // indices of key frames
};

struct Panel {
  std::string title;            // UTF-8; characters outside Latin-1 show as '?'
  Colour colour = {0.95f, 0.55f, 0.2f};  // the solid pose and its trail
  WorldPose ghost;              // reference pose (positions used); empty = none
  WorldPose pose;               // the pose drawn solid; empty = none
  std::shared_ptr<const Trail> trail;  // optional
  // One colour per joint (or empty: every bone in `colour`): joint j's colour on the
  // bones its rotation turns (j → each child, j → its End Sites) and on the
  // spheres at their far ends; the root's sphere in the root's colour.
  std::vector<Colour> joint_colours;
  double colour_scale_deg = 0.0;   // > 0: a viridis colour bar from 0 to this, labelled in degrees
  std::string corner;              // a line at the top left of the figure (frame, time)
  int label_joint = -1;            // ≥ 0: `joint_label` written next to this joint of `pose`
  std::string joint_label;
  std::optional<Bounds> view;      // the box this panel's camera frames; unset: the scene's
  std::shared_ptr<const ErrorStrip> strip;  // optional, under the figure
};

// What all panels share.
struct Scene {
  Skeleton skeleton;        // bones: joint → parent, End Site → joint
  // Of every pose drawn: frames the camera (unless a panel has its own view) and
  // places the grid (its height always; its extent around a panel's view when set).
  Bounds bounds;
  double bone_radius = 0;   // clip units; 0 = automatic (scene_bone_radius)
  bool axes = false;        // each joint's axes as an RGB triad, sized to the box framed (axes.h)
  ViewAngles view;
};

// 0.1 × the median non-zero bone length of the rest pose, kept within
// [0.004, 0.02] × the diagonal of `bounds`.
double scene_bone_radius(const Skeleton& skeleton, const Bounds& bounds);

// Limits on what render() accepts.
constexpr int kMaxImageSide = 8192;   // pixels, per side
constexpr int kMinPanelWidth = 64;    // pixels
constexpr int kMinPanelHeight = 48;   // pixels
constexpr int kSamples = 4;           // multisampling per pixel (fewer if the GL has fewer)

// Whether `panels` panels on `columns` columns (0 = automatic_columns) fit a
// width × height image within the limits above; the error is one line.
Status check_image_size(int width, int height, int panels, int columns = 0);

class Renderer {
 public:
  // Takes the context (current on this thread), loads GL, compiles the shaders and
  // loads the font. Errors: GL older than 3.3, missing entry points, no font.
  static Result<std::unique_ptr<Renderer>> create(std::unique_ptr<GLContext> context, Scene scene);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws `panels` row-major on a grid of `columns` (0 = automatic_columns) into a
  // width × height image. Errors: a side outside [1, kMaxImageSide], panels smaller
  // than kMinPanelWidth × kMinPanelHeight, no panels, a GL failure.
  // Deterministic: the same input gives the same pixels.
  Result<Image> render(const std::vector<Panel>& panels, int width, int height, int columns = 0);

  const Scene& scene() const;
  Backend backend() const;
  // The GL_RENDERER and GL_VERSION strings, e.g. for --verbose output.
  std::string gl_description() const;

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace rotinterp::render
