// rotinterp resample PATH... -o OUTDIR: a whole dataset resampled file by file on a
// work queue, its layout mirrored under OUTDIR, a progress line and the manifest.
#include "cmd_resample.h"
#include "common.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/csv.h"
#include "rotinterp/io/dataset.h"
#include "rotinterp/io/write.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <mutex>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

Status write_manifest(const std::string& path, const std::vector<FileRun>& runs, const ResampleOptions& opt) {
  static const CsvSchema schema = {"input",  "output",   "status",        "frame_time_written", "rate_hz",
                                   "rate",   "frames",   "duration_s",    "joints",             "output_frames",
                                   "method", "seconds",  "message",       "metres_per_unit",    "unit"};
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << schema.header();
    for (const FileRun& r : runs) {
      const bool read = r.status == "ok" || (r.status == "failed" && r.frames > 0);
      const bool ok = r.status == "ok";
      CsvRow row(schema);
      row << r.input << r.output.string() << r.status << r.frame_time
          << (r.rate ? fmt::format("{:.9g}", r.rate->hz()) : "") << (r.rate ? r.rate->to_string() : "")
          << (read ? std::to_string(r.frames) : "") << (read ? fmt::format("{:.9g}", r.duration) : "")
          << (read ? std::to_string(r.joints) : "") << (ok ? std::to_string(r.output_frames) : "") << opt.method
          << (ok ? fmt::format("{:.3f}", r.seconds) : "") << r.message
          << (read ? fmt::format("{}", r.unit.metres_per_unit) : "") << (read ? describe_unit(r.unit) : "");
      out << row.line();
    }
    return Ok{};
  });
}

// "1m05s", "42s".
std::string duration_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  return s >= 60 ? fmt::format("{}m{:02}s", s / 60, s % 60) : fmt::format("{}s", s);
}

}  // namespace

int run_resample_folder(const ResampleArgs& a, const ResampleOptions& opt) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.output, ec) ? !fs::is_directory(a.output, ec) : can_write_format(a.output))
    return fail_usage("output '" + a.output + "' is a file name; several inputs or a folder need an output directory");
  if (!a.format.empty() && !can_write_format(fs::path("x." + a.format)))
    return fail_usage("--format '" + a.format + "': unknown format (use bvh, fbx, glb, gltf or dae)");
  std::vector<fs::path> named(a.inputs.begin(), a.inputs.end());
  auto found = discover_inputs(named);
  if (!found) return fail(found.error());
  if (found->empty()) {
    std::string where;
    for (const std::string& p : a.inputs) where += (where.empty() ? "" : ", ") + p;
    return fail(where + ": no clip files found (looked for every format assimp imports)");
  }
  std::vector<std::string> files = *found;
  if (!a.shard.empty()) {
    auto shard = parse_shard(a.shard);
    if (!shard) return fail_usage(shard.error());
    files = shard_of(files, shard->first, shard->second);
  }
  auto plan = mirror_outputs(files, named, a.output, a.format);
  if (!plan) return fail(plan.error());
  for (const MirroredOutput& m : *plan) protect_input(m.input);

  WorkQueue queue(static_cast<unsigned>(a.jobs));
  // Joints in parallel only where fewer files than workers are in flight (the last ones).
  std::atomic<unsigned> in_flight{0};
  std::atomic<std::size_t> done{0};
  std::atomic<std::uintmax_t> bytes_done{0};
  std::uintmax_t bytes_total = 0;
  for (const MirroredOutput& m : *plan) bytes_total += fs::file_size(m.input, ec) * !ec;
  const bool show = !a.quiet && ::isatty(STDERR_FILENO);
  std::mutex progress_mutex;
  const auto started = std::chrono::steady_clock::now();
  auto report = [&] {
    if (!show) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double mb = static_cast<double>(bytes_done.load()) / 1e6;
    const double rate = elapsed > 0 ? mb / elapsed : 0.0;
    const double left = static_cast<double>(bytes_total - std::min(bytes_total, bytes_done.load())) / 1e6;
    std::lock_guard<std::mutex> lock(progress_mutex);
    std::fprintf(stderr, "\r\033[Kresample  %zu/%zu files  %.1f MB/s  ETA %s", done.load(), plan->size(), rate,
                 rate > 0 ? duration_text(left / rate).c_str() : "?");
  };
  auto no_stage = [](const std::string&) {};

  std::vector<std::future<FileRun>> futures;
  for (const MirroredOutput& m : *plan) {
    futures.push_back(queue.submit([&, m] {
      FileRun run;
      run.input = m.input;
      run.output = m.output;
      std::error_code size_error;  // this worker's own
      run.bytes = fs::file_size(m.input, size_error) * !size_error;
      if (a.skip_existing && fs::is_regular_file(m.output, size_error)) {
        run.status = "exists";
      } else if (Status mine = check_not_an_input(m.output); !mine) {
        run.status = "failed";
        run.message = mine.error();
      } else {
        ResampleOptions file_opt = opt;
        const unsigned now = ++in_flight;
        file_opt.threads = std::max(1u, queue.threads() / std::max(1u, now));
        std::error_code mkdir_error;
        fs::create_directories(m.output.parent_path(), mkdir_error);
        Status s = mkdir_error ? Status(make_error(m.output.parent_path().string() + ": " + mkdir_error.message()))
                               : resample_file(run, a, file_opt, no_stage);
        --in_flight;
        if (!s && s.error_kind() == ErrorKind::no_animation && found_in_directory(m.input, named)) {
          run.status = "no-animation";  // a mesh next to the clips, as eval skips it
        } else if (!s) {
          run.status = "failed";
          run.message = s.error();
        }
      }
      ++done;
      bytes_done += run.bytes;
      report();
      return run;
    }));
  }
  std::vector<FileRun> runs;
  std::size_t failed = 0, written = 0, existing = 0;
  for (auto& f : futures) {
    runs.push_back(f.get());
    const FileRun& r = runs.back();
    if (r.status == "failed") {
      ++failed;
      if (show) std::fprintf(stderr, "\r\033[K");
      fail(r.message);
    }
    written += r.status == "ok";
    existing += r.status == "exists";
  }
  end_progress(a.quiet);
  if (!a.manifest.empty())
    if (Status s = write_manifest(a.manifest, runs, opt); !s) return fail(s.error());
  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    fmt::print("{} file{} → {}: {} written, {} already there, {} failed, {} skipped (no animation); {:.1f} MB in "
               "{:.2f} s ({:.1f} MB/s), {} worker{}\n",
               runs.size(), runs.size() == 1 ? "" : "s", a.output, written, existing, failed,
               runs.size() - written - existing - failed, static_cast<double>(bytes_total) / 1e6, seconds,
               seconds > 0 ? static_cast<double>(bytes_total) / 1e6 / seconds : 0.0, queue.threads(),
               queue.threads() == 1 ? "" : "s");
  }
  return failed > 0 ? kExitPartial : kExitOk;
}

}  // namespace rotinterp::cli
