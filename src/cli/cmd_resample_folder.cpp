// rotinterp resample PATH... -o OUTDIR: a whole dataset resampled file by file on a
// folder run (batch/folder_run.h), its layout mirrored under OUTDIR, a progress line and the manifest.
#include "cmd_resample.h"
#include "common.h"
#include "folder_plan.h"
#include "progress_line.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/write.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

namespace rotinterp::cli {

namespace {

Status write_resample_manifest(const std::string& path, const FileRunReport& report, const std::vector<FileRun>& runs,
                               const ResampleOptions& opt) {
  static const std::vector<std::string> columns = {"frame_time_written", "rate_hz", "rate",    "frames",
                                                   "duration_s",         "joints",  "output_frames", "method",
                                                   "seconds",            "message", "metres_per_unit", "unit"};
  return write_manifest(path, report.outcomes, columns, [&](std::size_t i) -> std::vector<std::string> {
    const FileRun& r = runs[i];
    const FileOutcome& o = report.outcomes[i];
    const bool ok = o.status == FileStatus::ok;
    const bool read = ok || (o.status == FileStatus::failed && r.frames > 0);
    return {r.frame_time,
            r.rate ? fmt::format("{:.9g}", r.rate->hz()) : "",
            r.rate ? r.rate->to_string() : "",
            read ? std::to_string(r.frames) : "",
            read ? fmt::format("{:.9g}", r.duration) : "",
            read ? std::to_string(r.joints) : "",
            ok ? std::to_string(r.output_frames) : "",
            opt.method,
            ok ? fmt::format("{:.3f}", r.seconds) : "",
            o.message,
            read ? fmt::format("{}", r.unit.metres_per_unit) : "",
            read ? describe_unit(r.unit) : ""};
  });
}

}  // namespace

int run_resample_folder(const ResampleArgs& a, const ResampleOptions& opt) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.output, ec) ? !fs::is_directory(a.output, ec) : can_write_format(a.output))
    return fail_usage("output '" + a.output + "' is a file name; several inputs or a folder need an output directory");
  if (!a.format.empty() && !can_write_format(fs::path("x." + a.format)))
    return fail_usage("--format '" + a.format + "': unknown format (use " + format_names(writable) + ")");
  int exit_code = kExitOk;
  const std::optional<FolderPlan> plan = plan_folder_run(
      a.inputs, a.shard,
      [&](const std::vector<std::string>& files, const std::vector<fs::path>& named) {
        return mirror_outputs(files, named, a.output, a.format);
      },
      exit_code);
  if (!plan) return exit_code;

  std::vector<FileRun> runs(plan->outputs.size());
  std::vector<std::uintmax_t> bytes(plan->outputs.size());
  std::uintmax_t bytes_total = 0;
  for (std::size_t i = 0; i < plan->outputs.size(); ++i) {
    bytes[i] = fs::file_size(plan->outputs[i].input, ec) * !ec;
    bytes_total += bytes[i];
    runs[i].input = plan->outputs[i].input;
    runs[i].output = plan->outputs[i].output;
  }
  std::atomic<std::size_t> done{0};
  const ProgressFn progress = make_progress("resample", a.quiet, "files");
  const auto started = std::chrono::steady_clock::now();
  FileRunOptions run_options = plan->run_options(a.jobs, a.skip_existing, a.quiet);
  run_options.finished = [&](std::size_t) {
    const std::size_t now_done = ++done;
    if (progress) progress(now_done, plan->outputs.size());
  };
  auto no_stage = [](const std::string&) {};
  const FileRunReport report = run_files(plan->files, run_options, [&](std::size_t i, unsigned threads) -> Status {
    if (Status mine = check_not_an_input(runs[i].output); !mine) return mine;
    ResampleOptions file_opt = opt;
    file_opt.threads = threads;
    return resample_file(runs[i], a, file_opt, no_stage);
  });
  end_progress(a.quiet);
  if (!a.manifest.empty())
    if (Status s = write_resample_manifest(a.manifest, report, runs, opt); !s) return fail(s.error());
  const std::size_t failed = report.count(FileStatus::failed), written = report.count(FileStatus::ok),
                    existing = report.count(FileStatus::exists);
  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    fmt::print("{} file{} → {}: {} written, {} already there, {} failed, {} skipped (no animation); {:.1f} MB in "
               "{:.2f} s ({:.1f} MB/s), {} worker{}\n",
               runs.size(), runs.size() == 1 ? "" : "s", a.output, written, existing, failed,
               report.count(FileStatus::no_animation), static_cast<double>(bytes_total) / 1e6, seconds,
               seconds > 0 ? static_cast<double>(bytes_total) / 1e6 / seconds : 0.0, report.threads,
               report.threads == 1 ? "" : "s");
  }
  return failed > 0 ? kExitPartial : kExitOk;
}

}  // namespace rotinterp::cli
