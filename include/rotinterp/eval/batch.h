// The batch behind `rotinterp eval`: many clips, in parallel, into DIR/errors.csv,
// DIR/summary.json and PNG plots; and the merge of shard outputs.
//
// `jobs` worker threads of the folder run (batch/folder_run.h run_in_order) take
// (clip, method) pairs in input order — a clip is read
// and its reference prepared once, by the first of its pairs — so a long clip is
// shared by the workers too. Results are written in input order as they complete,
// and no worker starts clip i until clip i − 2·jobs has been written, so memory is
// bounded by the clips in flight, not by the batch. A file found in a directory
// that holds no animation (a mesh) is skipped quietly (summary.json "skipped"). A
// file that fails to load is
// reported (on_failure, summary.json "failed") and skipped; so is a clip on which
// a method fails, whole, so that every method is compared on the same clips.
#pragma once

#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/eval/summary.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// eval --per-frame: the angle error series of one clip × method × spacing.
struct PerFrameRequest {
  std::string clip;    // the clip id as in errors.csv (file, or file#take)
  std::string method;
  int keep_every = 1;
};

struct EvalOptions {
  std::vector<std::filesystem::path> inputs;  // files and directories (see batch/dataset.h)
  std::filesystem::path output_dir;           // created if missing
  ClipEvalOptions clip;                       // methods, keep_every, subframe, shell distance
  int jobs = 0;                               // worker threads; 0 = all cores
  int shard_index = 1, shard_count = 1;       // evaluate shard_of(files, index, count)
  bool plots = true;                          // write the plots (PNG and SVG)
  // Which takes of each file: empty, the first; a name or an index, that take; "all",
  // every take; a comma list of names and indices, those (io/takes.h). Each take evaluated is a clip of its own; in a file holding several
  // takes it is named file#take (the take's name, or its index when the name is
  // empty or not unique), even when only one of them is evaluated; a file of one
  // take keeps its plain path.
  std::string animation;
  // Metres per unit of files that state no unit (--unit; io/read.h ReadOptions::unit).
  std::optional<double> unit;
  // glTF buffers outside a file's folder are read (--allow-external-files; ReadOptions).
  bool allow_external_files = false;
  std::optional<PerFrameRequest> per_frame;   // also write DIR/per_frame.csv
  // What each clip is compared with. `name` is recorded in summary.json (options.truth):
  // "frames", the clip's own frames (`for_clip` unset); "synth", a synth clip's analytic
  // motion; "source", an FBX file's own curves. `for_clip` gives a clip file's truth; an
  // error fails that clip. Called from worker threads.
  struct Truth {
    std::string name = "frames";
    std::function<Result<TruthFn>(const std::string& file, const Clip& clip)> for_clip;
  } truth;
  ProgressFn progress;                                     // clips done / clips in all
  std::function<void(const EvalFailure&)> on_failure;      // called in input order, from the calling thread
};

struct EvalReport {
  Summary summary;
  std::vector<EvalFailure> failures;
  std::vector<std::string> skipped;  // files found in directories that hold no animation
  std::vector<ShortClip> too_short;  // clips evaluated at fewer spacings than asked, or none
  std::size_t files = 0;           // files in this run (this shard)
  std::size_t clips_evaluated = 0;
  double seconds = 0;              // wall time
};

// File names inside the output directory.
constexpr const char* kErrorsCsvName = "errors.csv";
constexpr const char* kSummaryJsonName = "summary.json";
constexpr const char* kClipsCsvName = "clips.csv";
constexpr const char* kPerFrameCsvName = "per_frame.csv";

// Runs the batch. Errors (nothing written) for bad options, no input files, an
// output that cannot be written, or a --per-frame clip that is not among those
// evaluated; load failures are in the report instead.
Result<EvalReport> run_eval(const EvalOptions& options);

// Combines the outputs of shard runs (directories holding errors.csv and
// summary.json) into `output_dir`: errors.csv byte-identical to a single run's,
// summary.json with the same results (run metadata: inputs and failures of all
// shards, time summed). Errors for missing files, runs with different options, or a
// clip present in two shards.
Result<EvalReport> merge_eval(const std::vector<std::filesystem::path>& shard_dirs,
                              const std::filesystem::path& output_dir, bool plots = true);

}  // namespace rotinterp
