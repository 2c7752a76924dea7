// A folder run's plan (its files, shard and outputs) and its failures, said the same way by every command.
#include "folder_plan.h"

#include "common.h"
#include "progress_line.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/files/run_guard.h"
#include "rotinterp/io/files/file_errors.h"

#include <new>
#include <tuple>
#include <utility>

namespace rotinterp::cli {

std::optional<FolderPlan> plan_folder_run(const std::vector<std::string>& inputs, const std::string& shard,
                                          const PlanOutputs& plan_outputs, int& exit_code) {
  FolderPlan run;
  run.named.assign(inputs.begin(), inputs.end());
  int shard_index = 1, shard_count = 1;
  if (!shard.empty()) {
    auto parsed = parse_shard(shard);
    if (!parsed) {
      exit_code = fail_usage(parsed.error());
      return std::nullopt;
    }
    std::tie(shard_index, shard_count) = *parsed;
  }
  auto files = find_run_inputs(run.named, shard_index, shard_count);
  if (!files) {
    exit_code = fail(files.error());
    return std::nullopt;
  }
  auto outputs = plan_outputs(*files, run.named);
  if (!outputs) {
    exit_code = fail(outputs.error());
    return std::nullopt;
  }
  run.outputs = std::move(*outputs);
  for (const MirroredOutput& m : run.outputs) {
    protect_input(m.input);
    run.files.push_back({m.input, m.output});
  }
  return run;
}

FileRunOptions FolderPlan::run_options(int jobs, bool skip_existing, bool quiet) const {
  FileRunOptions o;
  o.named = named;
  o.threads = thread_count(static_cast<unsigned>(jobs));
  o.skip_existing = skip_existing;
  o.on_failure = [quiet](const FileFailure& f) { print_file_failure(f, quiet); };
  return o;
}

void print_file_failure(const FileFailure& failure, bool quiet) {
  if (failure.kind == file_error::out_of_memory) {
    name_out_of_memory_file(failure.file);
    throw std::bad_alloc();
  }
  end_progress(quiet);
  fail(failure.message);
}

}  // namespace rotinterp::cli
