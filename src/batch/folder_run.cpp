// A folder run's inputs, its per-file jobs on the work queue, and its manifest.
#include "rotinterp/batch/folder_run.h"

#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/csv.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/io/files/file_errors.h"

#include <atomic>
#include <system_error>

namespace rotinterp {

namespace fs = std::filesystem;

std::string_view file_status_name(FileStatus status) {
  switch (status) {
    case FileStatus::ok: return "ok";
    case FileStatus::exists: return "exists";
    case FileStatus::no_animation: return "no-animation";
    case FileStatus::failed: return "failed";
  }
  return "failed";
}

Result<std::vector<std::string>> find_run_inputs(const std::vector<fs::path>& inputs, int shard_index, int shard_count) {
  if (shard_count < 1 || shard_index < 1 || shard_index > shard_count)
    return make_error("shard must be I/N with 1 ≤ I ≤ N");
  auto all = discover_inputs(inputs);
  if (!all) return all.failure();
  if (all->empty()) {
    std::string where;
    for (const fs::path& p : inputs) where += (where.empty() ? "" : ", ") + p.string();
    return make_error(where + ": no clip files found (looked for every format assimp imports)");
  }
  return shard_of(*all, shard_index, shard_count);
}

std::size_t FileRunReport::count(FileStatus status) const {
  return static_cast<std::size_t>(
      std::count_if(outcomes.begin(), outcomes.end(), [&](const FileOutcome& o) { return o.status == status; }));
}

FileRunReport run_files(const std::vector<RunFile>& files, const FileRunOptions& options, const FileJob& job) {
  FileRunReport report;
  const unsigned workers =
      static_cast<unsigned>(std::min<std::size_t>(thread_count(options.threads), std::max<std::size_t>(1, files.size())));
  report.threads = workers;
  std::atomic<unsigned> in_flight{0};
  std::atomic<std::size_t> done{0};
  const std::function<FileOutcome(std::size_t)> one = [&](std::size_t i) {
    const RunFile& f = files[i];
    FileOutcome o{f.input, f.output, FileStatus::ok, {}, ErrorKind::other};
    std::error_code ec;  // this worker's own
    if (options.skip_existing && !f.output.empty() && fs::is_regular_file(f.output, ec)) {
      o.status = FileStatus::exists;
    } else {
      // Joints in parallel only where fewer files than workers are in flight (the last ones).
      const unsigned now = ++in_flight;
      const Status s = job(i, std::max(1u, workers / std::max(1u, now)));
      --in_flight;
      if (!s && s.error_kind() == file_error::no_animation && found_in_directory(f.input, options.named)) {
        o.status = FileStatus::no_animation;
      } else if (!s) {
        o.status = FileStatus::failed;
        o.message = s.error();
        o.kind = s.error_kind();
      }
    }
    if (options.finished) options.finished(i);
    const std::size_t n = ++done;
    if (options.progress) options.progress(n, files.size());
    return o;
  };
  run_in_order<FileOutcome>(files.size(), workers, 2 * static_cast<std::size_t>(workers), one,
                            [&](std::size_t, FileOutcome o) {
                              if (o.status == FileStatus::failed) {
                                report.failures.push_back({o.input, o.message, o.kind});
                                if (options.on_failure) options.on_failure(report.failures.back());
                              }
                              report.outcomes.push_back(std::move(o));
                              return true;
                            });
  return report;
}

Status write_manifest(const fs::path& path, const std::vector<FileOutcome>& outcomes,
                      const std::vector<std::string>& columns,
                      const std::function<std::vector<std::string>(std::size_t)>& cells) {
  std::vector<std::string> all = {"input", "output", "status"};
  all.insert(all.end(), columns.begin(), columns.end());
  const CsvSchema schema(std::move(all));
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << schema.header();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const FileOutcome& o = outcomes[i];
      CsvRow row(schema);
      row << o.input << o.output.string() << std::string(file_status_name(o.status));
      for (const std::string& cell : cells(i)) row << cell;
      out << row.line();
    }
    return Ok{};
  });
}

}  // namespace rotinterp
