// rotinterp reduce PATH... -o OUTDIR: a whole dataset reduced file by file on a folder
// run (batch/folder_run.h), its layout mirrored under OUTDIR, a progress line and the manifest.
#include "cmd_reduce.h"
#include "common.h"
#include "folder_plan.h"
#include "progress_line.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/files/formats.h"

#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace rotinterp::cli {

namespace {

namespace fs = std::filesystem;

// The output of each input: resample's mirrored path (batch/dataset.h mirror_outputs),
// with the extension of `format`, or else the input's own where reduce writes it
// (fbx, glb, gltf), else json. Error when two inputs would share an output.
Result<std::vector<MirroredOutput>> reduce_outputs(const std::vector<std::string>& files,
                                                   const std::vector<fs::path>& named, const std::string& out_dir,
                                                   const std::string& format) {
  auto plan = mirror_outputs(files, named, out_dir, "");
  if (!plan) return plan.failure();
  std::map<fs::path, std::string> taken;
  for (MirroredOutput& m : *plan) {
    const std::string own = lower_extension(m.input);
    const FormatInfo* own_format = format_named(own);
    const bool kept = own_format && own_format->curves;  // a format of sparse keys keeps its own
    m.output.replace_extension(!format.empty() ? "." + format : kept ? own : ".json");
    auto [at, fresh] = taken.emplace(m.output, m.input);
    if (!fresh)
      return make_error("'" + at->second + "' and '" + m.input + "' would both be written to '" + m.output.string() +
                        "'; give --format or rename one");
  }
  return plan;
}

Status write_reduce_manifest(const std::string& path, const FileRunReport& report, const std::vector<ReduceFileRun>& runs,
                             const std::string& method, bool shell) {
  static const std::vector<std::string> columns = {"method",     "frames",     "joints",
                                                   "source_keys", "kept_keys", "kept_percent",
                                                   "max_rotation_error_deg", "max_shell_error_mm", "seconds", "message"};
  return write_manifest(path, report.outcomes, columns, [&](std::size_t i) -> std::vector<std::string> {
    const ReduceFileRun& r = runs[i];
    const FileOutcome& o = report.outcomes[i];
    const bool ok = o.status == FileStatus::ok;
    return {method,
            ok ? std::to_string(r.frames) : "",
            ok ? std::to_string(r.joints) : "",
            ok ? std::to_string(r.source_keys) : "",
            ok ? std::to_string(r.kept_keys) : "",
            ok ? fmt::format("{:.4f}", 100.0 * static_cast<double>(r.kept_keys) /
                                           static_cast<double>(std::max<std::size_t>(1, r.source_keys)))
               : "",
            ok ? fmt::format("{:.6g}", r.max_rotation_deg) : "",
            ok && shell ? fmt::format("{:.6g}", r.max_shell_mm) : "",
            ok ? fmt::format("{:.3f}", r.seconds) : "",
            o.message};
  });
}

}  // namespace

int run_reduce_folder(const ReduceArgs& a, const ReduceSetup& s) {
  std::error_code ec;
  const std::string& method = s.methods.front();
  if (a.output.empty()) return fail_usage("several inputs or a folder need an output directory (-o DIR)");
  if (fs::exists(a.output, ec) ? !fs::is_directory(a.output, ec) : reduce_output_problem(a.output, "slerp", false).empty())
    return fail_usage("output '" + a.output + "' is a file name; several inputs or a folder need an output directory");
  if (s.methods.size() > 1)
    return fail_usage("-m: a folder run writes one method's keys; the table of several is for one file");
  if (!a.report.empty()) return fail_usage("--report is for one file; a folder run writes --manifest FILE.csv");
  if (!a.format.empty()) {
    const FormatInfo* f = format_named(a.format);
    if (a.format != "json" && !(f && f->curves))
      return fail_usage("--format '" + a.format + "': unknown format (use json, " + format_names(keeps_curves) + ")");
    if (std::string problem = reduce_output_problem("x." + a.format, method, s.loop.has_value()); !problem.empty())
      return fail_usage(problem);
  }
  int exit_code = kExitOk;
  const std::optional<FolderPlan> plan = plan_folder_run(
      a.inputs, a.shard,
      [&](const std::vector<std::string>& files, const std::vector<fs::path>& named) {
        return reduce_outputs(files, named, a.output, a.format);
      },
      exit_code);
  if (!plan) return exit_code;

  std::vector<ReduceFileRun> runs(plan->outputs.size());
  std::atomic<std::size_t> done{0};
  const ProgressFn progress = make_progress("reduce", a.quiet, "files");
  const auto started = std::chrono::steady_clock::now();
  FileRunOptions run_options = plan->run_options(a.jobs, a.skip_existing, a.quiet);
  run_options.finished = [&](std::size_t) {
    const std::size_t now_done = ++done;
    if (progress) progress(now_done, plan->outputs.size());
  };
  const FileRunReport report = run_files(plan->files, run_options, [&](std::size_t i, unsigned threads) -> Status {
    const MirroredOutput& m = plan->outputs[i];
    if (Status mine = check_not_an_input(m.output); !mine) return mine;
    if (std::string problem = reduce_output_problem(m.output.string(), method, s.loop.has_value()); !problem.empty())
      return make_error(m.input + ": " + problem);
    ReduceFileOptions o;
    o.output = m.output.string();
    o.threads = threads;
    o.show_progress = false;
    o.print = false;
    return reduce_one_file(m.input, a, s, o, runs[i]);
  });
  end_progress(a.quiet);
  if (!a.manifest.empty())
    if (Status st = write_reduce_manifest(a.manifest, report, runs, method, s.mm > 0.0); !st) return fail(st.error());
  const std::size_t failed = report.count(FileStatus::failed), written = report.count(FileStatus::ok),
                    existing = report.count(FileStatus::exists);
  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    fmt::print("{} file{} → {}: {} written, {} already there, {} failed, {} skipped (no animation); method {}, "
               "{:.2f} s, {} worker{}\n",
               runs.size(), runs.size() == 1 ? "" : "s", a.output, written, existing, failed,
               report.count(FileStatus::no_animation), method, seconds, report.threads, report.threads == 1 ? "" : "s");
  }
  return failed > 0 ? kExitPartial : kExitOk;
}

}  // namespace rotinterp::cli
