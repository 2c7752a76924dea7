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
#include "rotinterp/render/layout.h"

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

// An error-over-time strip under a panel, with axes: time in seconds along the
// bottom, degrees up the left. One line per series (a method's max over joints, say)
// in its colour; a clip longer than the strip is wide is drawn as a per-column
// min/max band. A cursor at the panel's frame, keys ticked.
struct StripLine {
  std::vector<float> deg;  // degrees, per frame of the range
  Colour colour = {0.93f, 0.93f, 0.93f};
  float alpha = 1.0f;      // < 1: a secondary line (drawn dimmer)
};
struct ErrorStrip {
  std::vector<StripLine> lines;    // every line the same length: the frames of the range
  std::string quantity;            // what the lines are, e.g. "max over joints"
  double start_s = 0.0;            // time of the range's first frame, seconds (the time axis)
  double end_s = 0.0;              // and of its last
  double scale_deg = 1.0;          // the degree axis' top (shared by every image of a run)
  std::size_t cursor = 0;          // index of the panel's frame
  std::vector<std::size_t> keys;   // indices of key frames
};

// A pose drawn solid in one colour beside the panel's own (the overlay view: a
// method each), named in the panel's legend.
struct Figure {
  WorldPose pose;
  Colour colour = {0.95f, 0.55f, 0.2f};
  std::string legend;  // its line in the legend; empty: none
};

struct Panel {
  std::string title;            // UTF-8; characters outside Latin-1 (and ≥ … —) show as '?'
  Colour colour = {0.95f, 0.55f, 0.2f};  // the solid pose and its trail
  WorldPose ghost;              // reference pose (positions used); empty = none
  WorldPose pose;               // the pose drawn solid; empty = none
  std::shared_ptr<const Trail> trail;  // optional
  // One colour per joint (or empty: every bone in `colour`): joint j's colour on the
  // bones its rotation turns (j → each child, j → its End Sites) and on the
  // spheres at their far ends; the root's sphere in the root's colour.
  std::vector<Colour> joint_colours;
  double colour_scale_deg = 0.0;   // > 0: a viridis colour bar from 0 to this, labelled in degrees
  bool colour_scale_saturated = false;  // errors above the scale exist (drawn at its top): labelled "≥ N°"
  std::vector<Figure> figures;     // more poses drawn solid over the ghost, each in its colour
  std::string ghost_legend;        // non-empty: the ghost's line in the legend (e.g. "truth")
  std::string corner;              // a line at the top left of the figure (frame, time)
  int label_joint = -1;            // ≥ 0: `joint_label` written next to this joint of `pose`
  int label_figure = -1;           // ≥ 0: of figures[label_figure]'s pose instead
  std::string joint_label;
  std::optional<Bounds> view;      // the box this panel's camera frames; unset: the scene's
  std::shared_ptr<const ErrorStrip> strip;  // optional, under the figure
};

// What all panels share.
struct Scene {
  Skeleton skeleton;        // bones: joint → parent, End Site → joint
  // Per joint (or empty): the bones it turns are drawn thin, e.g. from a ground
  // marker at the root to the hips of a figure that travels away from it.
  std::vector<bool> thin;
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

// The camera of a width × height panel and the viewport it draws into (y downwards,
// in the panel's pixels): what the renderer projects the panel's poses with.
struct PanelCamera {
  Camera camera;
  Rect viewport;
};
PanelCamera panel_camera(const Scene& scene, const Panel& panel, int width, int height);

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
