// Plots of an evaluation (PLplot's cairo driver), each as PNG and SVG, written atomically.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/eval/summary.h"
#include "rotinterp/io/files/atomic_file.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {

// File names inside the output directory.
constexpr const char* kSpacingPlotName = "error_vs_spacing.png";
constexpr const char* kWorstClipPlotName = "worst_clip_joints.png";
constexpr const char* kClipsPlotName = "clip_errors.png";
// Every file the plots are written to: the three PNGs and their SVGs (same stem).
std::vector<std::string> plot_file_names();

// error_vs_spacing: against keep_every (log₂), three panels (log₁₀ degrees): RMS
// over all samples, the median over clips of the clip RMS, and the max.
// worst_clip_joints: RMS angle per joint of the worst clip at its largest keep_every.
// clip_errors: each clip's RMS angle at the largest keep_every it was evaluated at.
// Every method has its own colour, marker and dash pattern (palette/method_style.h),
// and its points are offset slightly sideways so that methods with equal values stay
// visible. Axes, texts and legends go where eval/plot_layout.h puts them.

// Not thread-safe (PLplot has global state): call from one thread.
Status write_plots(const Summary& summary, const std::filesystem::path& dir);
// The same, drawn into finished but uncommitted outputs appended to `outputs`, for
// a caller that commits them together with other files (commit_together).
Status draw_plots(const Summary& summary, const std::filesystem::path& dir,
                  std::vector<std::unique_ptr<AtomicOutput>>& outputs);

}  // namespace rotinterp
