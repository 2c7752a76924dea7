// What reduce's one-file run (cmd_reduce.cpp), one file's work (cmd_reduce_file.cpp)
// and its folder run (cmd_reduce_folder.cpp) share: the command's arguments, the
// options parsed once for every file, and the step that reduces and writes one file.
#pragma once

#include "options.h"  // LoopRequest
#include "rotinterp/core/result.h"
#include "rotinterp/reduce/reduce.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

struct ReduceArgs {
  std::vector<std::string> inputs;
  std::string output, methods = "slerp", report, anim, translation = "cubic";
  std::string shell_distance, unit, loop = "off";
  std::vector<std::string> tolerance, tolerance_for;
  bool quiet = false;
  bool allow_external_files = false;
  // Folder runs.
  int jobs = 0;
  std::string shard, format, manifest;
  bool skip_existing = false;
};

// One --tolerance-for item: JOINT=LIST, LIST as --tolerance takes it.
struct JointBudget {
  std::string joint;
  double deg = 0.0, mm = 0.0;
};

// The options as parsed once, before any clip is read; lengths in metres and
// millimetres, converted per clip by its unit.
struct ReduceSetup {
  std::vector<std::string> methods;  // in the order listed; the output gets the first
  TranslationInterp translation = TranslationInterp::cubic;
  double deg = 0.0, mm = 0.0, shell_m = 0.0;
  std::optional<double> unit_m;
  std::optional<LoopRequest> loop;
  std::vector<JointBudget> per_joint;
};

// Every option check that needs no input (the output's format aside). Errors are usage errors.
Result<ReduceSetup> parse_reduce_setup(const ReduceArgs& a);

// ".JSON" → ".json": a path's extension, lower case.
std::string lower_extension(const std::string& path);

// Whether `output` is a format reduce writes, for `method` and `--loop`; "" when so,
// else the usage line.
std::string reduce_output_problem(const std::string& output, const std::string& method, bool loop);

// What one file's run found and reduced with the first method: a manifest row after
// its first columns (batch/folder_run.h FileOutcome).
struct ReduceFileRun {
  std::size_t frames = 0, joints = 0, source_keys = 0, kept_keys = 0;
  double max_rotation_deg = 0.0, max_shell_mm = 0.0, seconds = 0.0;
  bool usage_error = false;  // a --tolerance-for joint the clip does not have
  std::string kept;          // a character kept (.fbx, .glb/.gltf): "OUT: what passed through kept"
};

// How one file is reduced: where its output and report go (either may be empty),
// the reduction's worker count, and what it shows: the per-method progress line and
// the lines on stdout (table, summary), which a folder run leaves out.
struct ReduceFileOptions {
  std::string output, report;
  unsigned threads = 0;
  bool show_progress = true;
  bool print = true;
};

// Reads `input`, reduces it with every method of `s` and writes the output and the
// report, filling `run`. Errors name the file.
Status reduce_one_file(const std::string& input, const ReduceArgs& a, const ReduceSetup& s,
                       const ReduceFileOptions& o, ReduceFileRun& run);

// reduce PATH... -o OUTDIR: every clip found, its layout mirrored under OUTDIR,
// `a.jobs` files at once; the manifest when asked. Returns the exit code.
int run_reduce_folder(const ReduceArgs& a, const ReduceSetup& s);

}  // namespace rotinterp::cli
