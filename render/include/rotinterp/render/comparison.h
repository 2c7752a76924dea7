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
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/renderer.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp::render {

// Frames start, start + step, … up to and including end.
struct FrameRange {
  std::size_t start = 0;
  std::size_t end = 0;
  std::size_t step = 1;
};
// "START:END:STEP", "START:END" (step 1) or "START" (one frame); END ≥ START, STEP ≥ 1.
Result<FrameRange> parse_frame_range(std::string_view text);
// "WxH", both positive integers (limits are checked by render()).
Result<std::pair<int, int>> parse_size(std::string_view text);

struct ComparisonOptions {
  std::vector<std::string> methods;   // names in methods(); at least one
  std::size_t keep_every = 10;        // N ≥ 1: keys at frames 0, N, 2N, … and the last
  // Unset: 8 frames spread evenly over the clip, each halfway between two keys
  // (where interpolation errs most); every frame when there are fewer.
  std::optional<FrameRange> frames;
  int width = 960;                    // pixels, each frame image
  int height = 540;
  std::string trail_joint;            // non-empty: draw this joint's bone-direction trail
  bool sheet = false;                 // also write sheet.png: a row per method, a column per frame
  std::optional<Backend> backend;     // unset: default_backend()
  ProgressFn progress;                // (images written, images in all), from worker threads
};

struct ComparisonResult {
  std::vector<std::filesystem::path> files;  // in frame order, then the sheet
  std::string gl;                            // renderer and GL version
};

// The angular error of a rebuilt pose at one frame, degrees: mean and max over the
// animated joints (every joint when none is animated) — what a panel's title shows.
struct FrameError {
  double mean = 0.0;
  double max = 0.0;
};

// `method`'s error at every frame of the clip (clip/frames.h, the frames eval
// measures) when rebuilt from every keep_every-th frame.
Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every);

// The frames the options select in `clip` (checked against its frame count).
Result<std::vector<std::size_t>> comparison_frames(const Clip& clip, const ComparisonOptions& options);

// Renders the comparison into `out_dir` (created if missing): frame_NNNNNN.png per
// frame (NNNNNN the frame number, zero-padded to 6), and sheet.png with --sheet.
// Errors (one line): unknown method or joint, frames outside the clip, a size
// outside limits, a backend that is not available, an unwritable directory.
Result<ComparisonResult> render_comparison(const Clip& clip, const std::filesystem::path& out_dir,
                                           const ComparisonOptions& options);

}  // namespace rotinterp::render
