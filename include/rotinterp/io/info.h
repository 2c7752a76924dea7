// What a clip file holds: format, animations, the selected clip, warnings and
// oddities — the data behind `rotinterp info`, and its facts, computed once.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/files/bvh_layout.h"
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

// One joint as `info` describes it.
struct JointFacts {
  std::string name;
  std::optional<std::string> parent;            // none for a root
  std::size_t depth = 0;                        // 0 for a root
  std::vector<Channel> channels;                // the file's channel layout (BVH's CHANNELS), else none
  std::size_t rotation_keys = 0;
  std::optional<std::size_t> translation_keys;  // none: the joint has no translation track
};

// What `rotinterp info` says of a read clip, computed once (clip_facts) and printed
// as text (the CLI) or JSON (clip_info_json). Times in seconds, sizes in metres.
struct ClipFacts {
  std::size_t frames = 0;
  double frame_time = 0.0;
  std::string frame_time_written;  // as the file wrote it (BVH's Frame Time), else empty
  // The rate every command uses (resample too): BVH ".0333330" is 30 Hz, NTSC
  // 30000/1001; none where the keys are not on a uniform grid.
  std::optional<Rate> rate;
  bool rate_stated = false;  // the selected take's rate is the file's word (AnimationSummary)
  double file_rate_hz = 0.0; // the file's own rate where it states one (resample's default), else 0
  double start = 0.0, end = 0.0, duration = 0.0;
  double size_m = 0.0;       // the first pose's largest side
  std::vector<JointFacts> joints;
  std::vector<std::string> translated;  // the joints with a translation track, in joint order
  std::size_t channels = 0;             // the joints' channels in all (BVH's CHANNELS lines)
  std::size_t end_sites = 0;
  std::optional<LoopCheck> cycle;       // none where the check cannot run (no frame rate, < 3 frames)
  std::vector<std::string> oddities;    // clip_oddities
};
ClipFacts clip_facts(const ClipFileInfo& info);

// What `rotinterp info --json` prints for `info` read from `path` (written as
// given): its clip_facts as one JSON document, 2-space indented, the one definition
// the CLI and the Python module's rotinterp.info share.
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
