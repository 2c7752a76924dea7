// `rotinterp render` as a library call: a clip, reduced to keys every N frames,
// rebuilt by several interpolators and drawn side by side, one PNG per frame (and
// optionally a contact sheet).
//
// Frames are the source's frames, numbered from 0: the key times of its densest
// track when that track has a key on every frame (BVH), else start + k·frame_time. The reference ("original") pose of frame k uses
// the source's key at that time; between the keys of a sparse track it is the
// geodesic (slerp) between them, and translation is linear between its keys.
// Keys kept for the methods: frames 0, N, 2N, … and always the last frame. Only
// rotations are rebuilt; every panel uses the reference translations, so panels
// differ by rotation interpolation alone.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/rebuild.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/source_method.h"
#include "rotinterp/render/axes.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/loop_play.h"
#include "rotinterp/render/renderer.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::render {

// Frames start, start + step, … up to and including end.
struct FrameRange {
  std::size_t start = 0;
  std::size_t end = 0;
  std::size_t step = 1;
};

// How the methods are shown.
enum class View {
  overlay,  // one panel: the truth as a pale ghost, each method over it in its colour, a legend
  side,     // a panel per method, side by side, each over the ghost
};
// How the rebuilt poses of side panels are coloured (the overlay: by method).
enum class Colouring {
  error,   // each bone by its joint's angular error (viridis, one scale for the whole run)
  method,  // one colour per method (its place in methods())
};
// Where the camera looks from.
enum class CameraMode {
  automatic,  // follow when the pelvis travels farther than the skeleton's height over the frames drawn
  fixed,      // one view framing every pose of the frames drawn
  follow,     // a view that follows the smoothed pelvis (or the focus joint)
};

struct ComparisonOptions {
  std::vector<std::string> methods;   // names in methods(), or "source" with `source`; at least one
  // The panel of a method named "source" (kSourceMethodName): the file's own motion,
  // not rebuilt from keys; its error is against the clip's frames like any panel's.
  SourceMotion source;
  std::size_t keep_every = 10;        // N ≥ 1: keys at frames 0, N, 2N, … and the last
  // Unset: 8 frames spread evenly over the clip, each halfway between two keys
  // (where interpolation errs most); every frame when there are fewer — or, with
  // a video, every frame of the clip.
  std::optional<FrameRange> frames;
  int width = 960;                    // pixels, each frame image
  int height = 540;
  std::string trail_joint;            // non-empty: draw this joint's bone-direction trail
  double trail_window = 1.0;          // seconds either side of the frame shown on the trail; 0: all frames drawn
  bool sheet = false;                 // also write sheet.png: a row per panel, a column per frame
  View view = View::overlay;
  Colouring colouring = Colouring::error;
  CameraMode camera = CameraMode::automatic;
  // Empty: the camera frames the body (find_body in views.h: not a ground marker at
  // the root) and follows its pelvis; else it follows this joint and frames its limb.
  std::string focus_joint;
  AxesMode axes = AxesMode::automatic;  // each joint's axes as an RGB triad (axes.h)
  bool strip = true;                  // an error-over-time strip under each panel
  bool pngs = true;                   // write frame_NNNNNN.png (and sheet.png) into the output directory
  std::filesystem::path video;        // non-empty: also encode the frames into this .mp4 or .gif
  double video_fps = 0.0;             // frames per second of the video; 0: the clip's rate / frame step
  // --loop (render/loop_play.h): the cycle played twice, each method on its periodic
  // curve; frames are numbered over both periods, and unset `frames` (without a
  // video) are those from one key interval before the seam to one after it.
  std::optional<LoopPlay> loop;
  std::optional<Backend> backend;     // unset: default_backend()
  ProgressFn progress;                // (images done, images in all), from worker threads
};

struct ComparisonResult {
  std::vector<std::filesystem::path> files;  // in frame order, then the sheet, then the video
  std::string gl;                            // renderer and GL version
  bool followed = false;                     // whether the camera followed
  std::size_t video_frames = 0;
  double video_fps = 0.0;
};

// `method`'s error at every frame of the clip (clip/rebuild.h FrameError: what a
// panel's title shows) when rebuilt from every keep_every-th frame.
// With `loop`, at every frame of the cycle played twice (render/loop_play.h).
// `method` "source" is `source`'s motion (no loop).
Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every,
                                                  const std::optional<LoopPlay>& loop = std::nullopt,
                                                  const SourceMotion& source = {});

// The frames the options select in `clip` (checked against its frame count).
Result<std::vector<std::size_t>> comparison_frames(const Clip& clip, const ComparisonOptions& options);

// What render_comparison draws, computed before any GL: the scene the panels share,
// the frames selected and each frame's panels (poses, the camera's box, colours,
// strip, trail) — for tests and for callers that draw them elsewhere.
class ComparisonPlan {
 public:
  // Checks the options (the errors render_comparison gives, but those of writing)
  // and rebuilds the methods. `clip` must outlive the plan.
  static Result<ComparisonPlan> make(const Clip& clip, const ComparisonOptions& options);
  ComparisonPlan(ComparisonPlan&&) noexcept;
  ComparisonPlan& operator=(ComparisonPlan&&) noexcept;
  ~ComparisonPlan();

  const Scene& scene() const;
  const std::vector<std::size_t>& frames() const;  // numbered over both periods with --loop
  int columns() const;                              // panels per row of a frame's image
  bool followed() const;                            // whether the camera follows
  double video_fps() const;                         // the clip's rate over the frame step
  struct Frame {
    std::vector<Panel> panels;  // as drawn in the frame's image
    std::vector<Panel> cells;   // its column of sheet.png, a cell per panel
  };
  Frame frame(std::size_t i) const;  // of frames()[i]

 private:
  struct Impl;
  explicit ComparisonPlan(std::unique_ptr<Impl> impl);
  // make's work; with `cycle` (--loop) its two periods are the clip drawn.
  static Result<ComparisonPlan> plan(const Clip& clip, const ComparisonOptions& options,
                                     std::optional<CyclePlayedTwice> cycle);
  std::unique_ptr<Impl> impl_;
};

// Renders the comparison: into `out_dir` (created if missing; unused without
// pngs) frame_NNNNNN.png per frame (NNNNNN the frame number, zero-padded to 6),
// and sheet.png with --sheet; the video when asked.
// Side panels: the title (method, mean and max error over joints, "(key)" on kept
// keys), the frame number and time at the top left, the rebuilt pose coloured by
// error (a colour bar on one scale for the whole run, the worst joint labelled) or
// by method, the ghost of the original, the trail inset, and the error strip with
// time and degree axes. The overlay: one panel, every method's pose in its colour
// over the ghost, a legend with each method's errors, the worst joint labelled, one
// strip with a line per method.
// Errors (one line): unknown method or joint, "source" without `source` or with
// a loop, frames outside the clip, a size outside limits, a backend that is not available, an unwritable directory, a
// video that cannot be made (format, size, ffmpeg).
Result<ComparisonResult> render_comparison(const Clip& clip, const std::filesystem::path& out_dir,
                                           const ComparisonOptions& options);

}  // namespace rotinterp::render
