// What a clip file holds: format, animations, the selected clip, warnings and
// oddities — the data behind `rotinterp info`.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/record/clip_file.h"
#include "rotinterp/io/read.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// Reads `path` like read_clip() and also reports what the file holds.
Result<ClipFileInfo> inspect_clip(const std::filesystem::path& path, const ReadOptions& options = {});
// The same, whole: a failed reading still gives what it found before it (its
// warnings; what a file without animation holds, info.holds).
ReadOutcome inspect_clip_outcome(const std::filesystem::path& path, const ReadOptions& options = {});
// inspect_clip_outcome() as `info` reads: an FBX with its own curves too (ReadOptions::
// read_curves), so that its takes show in file time (assimp re-bases them); where our
// reader of the curves fails and they were not asked for, without them.
ReadOutcome inspect_clip_for_info(const std::filesystem::path& path, ReadOptions options);

// Things about a valid clip a user may want to know, one line each: non-uniform
// key spacing, joints without keys, tracks with differing key counts or spans,
// negative times.
std::vector<std::string> clip_oddities(const Clip& clip);

// What `rotinterp info --json` prints for `info` read from `path` (written as
// given): one JSON document, 2-space indented, the one definition the CLI and the
// Python module's rotinterp.info share.
std::string clip_info_json(const std::string& path, const ClipFileInfo& info);
// What `rotinterp info --curves --json` prints: {"curves": [{"node", "property",
// "channel", "layer", "default", "pre_extrapolation", "post_extrapolation",
// "keys": [{"t", "ticks", "value", "interpolation", "tangent", "left_slope",
// "right_slope", "left_weight", "right_weight", …}], "samples": […]}]} for the
// selected take of info.curves (2-space indented). `sample_hz` > 0 adds "samples":
// the curve at k/sample_hz s, k = 0, 1, … up to the take's end (FBX time 0 is t = 0);
// "t" is in seconds, slopes in value per second (fbx_curve_eval.h).
std::string curves_info_json(const ClipFileInfo& info, double sample_hz);
// The take info --curves describes: the selected animation's, else the first; nullptr
// when the file has no curves.
const FbxTake* selected_take(const ClipFileInfo& info);

// Its "unit" object (clip/units.h), as JSON text; info --summary's rows use it too.
std::string unit_info_json(const ClipUnit& unit);

}  // namespace rotinterp
