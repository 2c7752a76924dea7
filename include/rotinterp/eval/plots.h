// PNG plots of an evaluation (PLplot, pngcairo driver), written atomically.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/eval/summary.h"
#include "rotinterp/io/atomic_file.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace rotinterp {

// File names inside the output directory.
constexpr const char* kSpacingPlotName = "error_vs_spacing.png";
constexpr const char* kWorstClipPlotName = "worst_clip_joints.png";

// error_vs_spacing.png: RMS and max angle (degrees, log scale) against keep_every
// (log₂ scale), one colour per method. worst_clip_joints.png: RMS angle per joint of
// the worst clip at its largest keep_every, one colour per method. Not thread-safe
// (PLplot has global state): call from one thread.
Status write_plots(const Summary& summary, const std::filesystem::path& dir);
// The same, drawn into finished but uncommitted outputs appended to `outputs`, for
// a caller that commits them together with other files (commit_together).
Status draw_plots(const Summary& summary, const std::filesystem::path& dir,
                  std::vector<std::unique_ptr<AtomicOutput>>& outputs);

}  // namespace rotinterp
