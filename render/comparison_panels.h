// The panels of a comparison frame, from the rebuild: one per method side by side,
// or one overlay of every method on the truth; the run's one colour scale and its
// error strips (private to render/).
#pragma once

#include "rotinterp/clip/rebuild.h"
#include "rotinterp/render/renderer.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::render {

// The fraction of joint errors over a run that its colour scale holds; the rest
// are drawn saturated.
inline constexpr double kColourScaleFraction = 0.99;

// One colour scale for every image of a run: error_scale() of the
// kColourScaleFraction quantile of the non-zero joint errors of every method at
// every frame drawn; `saturated` when some error lies above it.
struct RunScale {
  double deg = 1.0;
  bool saturated = false;
};
RunScale run_colour_scale(const RebuiltClip& rebuild, std::size_t methods, const std::vector<std::size_t>& frames);

// What every frame's panels share.
struct PanelPlan {
  std::vector<std::string> methods;
  bool overlay = false;            // one panel of every method over the truth
  bool error_colours = false;      // (side) bones coloured by error on `scale`
  RunScale scale;
  std::vector<Colour> colours;     // per method
  std::optional<Bounds> view;      // the camera's box, the same in every frame (fixed)
  std::vector<Bounds> moving;      // or per frame [f - first] (follow)
  std::size_t first = 0;           // the first frame of the strips and views
  std::vector<std::shared_ptr<ErrorStrip>> strips;  // per panel, or empty
};

// The strips of the frames first…last: (side) each method's max and mean over
// joints; (overlay) one strip, a max line per method. One degree scale for all:
// the error that kRobustFraction of the frames stay below.
std::vector<std::shared_ptr<ErrorStrip>> error_strips(const RebuiltClip& rebuild, const PanelPlan& plan,
                                                      std::size_t first, std::size_t last);

// Frame f's panels, and each method's error there (for the sheet).
struct FramePanels {
  std::vector<Panel> panels;
  std::vector<FrameError> errors;               // per method
  std::vector<std::vector<double>> joint_error; // per method, per joint
};
FramePanels frame_panels(const RebuiltClip& rebuild, const PanelPlan& plan, std::size_t f, const WorldPose& ghost);

// The sheet of `frames` columns and `rows` rows of a frame image's `panel`, each
// cell shrunk so that the sheet fits kMaxImageSide: its size (x, y 0).
Rect sheet_size(const Rect& panel, std::size_t frames, int rows);

// Frame f's cells of the sheet: its panels without the corner line, titled with
// the frame and what their numbers are.
std::vector<Panel> sheet_cells(const PanelPlan& plan, const FramePanels& frame, std::size_t f);

}  // namespace rotinterp::render
