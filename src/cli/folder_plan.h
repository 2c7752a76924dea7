// A folder run as the commands start it (resample and reduce, -o DIR): the clip files
// found under the named inputs and their outputs, and a failed file said on one line.
#pragma once

#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/core/result.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

// A file of a folder run that failed (batch/folder_run.h), said the same way by every
// command: the progress line cleared, then "rotinterp: <message>" on stderr. Out of
// memory ends the run instead: main's one line naming the file, exit 1.
void print_file_failure(const FileFailure& failure, bool quiet);
// What a folder run works on: the named inputs, the clip files found under them
// (shard I/N of them, `shard` as --shard gave it), each one's output as `plan_outputs`
// places it under -o DIR, and each as a run file. The inputs are protected from
// being written over. On error it prints the line and sets `exit_code` (usage for a
// bad --shard, failure otherwise).
struct FolderPlan {
  std::vector<std::filesystem::path> named;
  std::vector<MirroredOutput> outputs;
  std::vector<RunFile> files;
  // How run_files runs it: its named inputs, -j workers, --skip-existing, and each
  // failure printed as its one line (print_file_failure).
  FileRunOptions run_options(int jobs, bool skip_existing, bool quiet) const;
};
using PlanOutputs = std::function<Result<std::vector<MirroredOutput>>(const std::vector<std::string>& files,
                                                                      const std::vector<std::filesystem::path>& named)>;
std::optional<FolderPlan> plan_folder_run(const std::vector<std::string>& inputs, const std::string& shard,
                                          const PlanOutputs& plan_outputs, int& exit_code);

}  // namespace rotinterp::cli
