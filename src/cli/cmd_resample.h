// What resample's one-file run (cmd_resample.cpp), one file's work
// (cmd_resample_file.cpp) and its folder run (cmd_resample_folder.cpp) share: the
// command's arguments, a file's run, and the step that reads, resamples and writes one file.
#pragma once

#include "options.h"  // LoopRequest
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/write_options.h"
#include "rotinterp/io/source_motion.h"

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

struct ResampleArgs {
  std::vector<std::string> inputs;
  std::string output;
  std::string fps, keep_every, method = kDefaultResampleMethod, translation = "cubic", range, anim, bvh_order = "ZXY";
  std::vector<std::string> method_for;
  bool quiet = false;
  bool fbx_ascii = false;
  // Folder runs.
  int jobs = 0;
  std::string shard, format, manifest;
  bool skip_existing = false;
  bool allow_external_files = false;
  std::string unit, out_unit;  // as written; parsed into:
  std::optional<double> unit_m, out_unit_m;  // metres per unit
  std::string loop = "off";                  // --loop as written; parsed into:
  std::optional<LoopRequest> loop_request;
};

// What one file's run found and wrote: a row of the manifest after its first columns
// (batch/folder_run.h FileOutcome: input, output, status, message).
struct FileRun {
  std::string input;
  std::filesystem::path output;
  std::string frame_time;     // as written in the file (BVH), else empty
  std::optional<Rate> rate;   // as recognized
  std::optional<Rate> output_rate;
  std::size_t frames = 0, joints = 0, output_frames = 0;
  double duration = 0.0, seconds = 0.0;
  ClipUnit unit;             // the input's (clip/units.h)
  double output_metres_per_unit = 0.0;
  std::string cycle;  // --loop: the cycle's summary (clip/resample_loop.h)
  std::size_t replayed = 0;  // --method source: joints evaluated from the file's own motion
  std::string replays;       // … which is (FileSource::replays): "the file's curves", …
  std::size_t copied_curves = 0;  // --method source to FBX without --fps: joints whose curves were written back
  std::string kept;               // FBX character to FBX: what passed through (io/fbx/fbx_character.h)
  std::chrono::steady_clock::time_point started;
};

// A file (one take) read and resampled, before it is written.
struct ResampledFile {
  Clip clip;
  std::optional<FileSource> own;  // --method source: the file's own motion
  std::vector<std::string> keep;  // --method-for joints: they keep their method
};

// Reads and resamples one file (its take a.anim), filling `run`; `stage` names each step.
Result<ResampledFile> resample_input(FileRun& run, const ResampleArgs& a, const ResampleOptions& opt,
                                     const std::function<void(const std::string&)>& stage);
// How resampled clips are written: --bvh-order, --fbx-ascii, warnings, threads.
WriteOptions resample_write_options(const ResampleArgs& a, const ResampleOptions& opt, FileRun& run);
// Writes it to run.output (the source's own FBX curves where they go back as stored).
Status write_resampled(FileRun& run, const ResampledFile& done, const ResampleArgs& a, const ResampleOptions& opt,
                       const std::function<void(const std::string&)>& stage);

// Reads, resamples and writes one file, filling `run`; `stage` names each step.
Status resample_file(FileRun& run, const ResampleArgs& a, const ResampleOptions& opt,
                     const std::function<void(const std::string&)>& stage);

// resample PATH... -o OUTDIR: every clip found, its layout mirrored under OUTDIR,
// `a.jobs` files at once; the manifest when asked. Returns the exit code.
int run_resample_folder(const ResampleArgs& a, const ResampleOptions& opt);

}  // namespace rotinterp::cli
