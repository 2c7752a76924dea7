// Running a job over many files: the one facility behind every folder run
// (resample, eval, info --summary).
//
//  * find_run_inputs: the clip files named or found in folders (batch/dataset.h
//    discover_inputs), this shard's part of them;
//  * run_in_order: tasks on one work queue (core/work_queue.h) of the caller's
//    thread count, a bounded number in flight, results handed back in input order;
//  * run_files: one job per file on top of it — skip-existing, the output's folder
//    made, a mesh found next to the clips skipped quietly, every other error kept
//    as a FileFailure with its ErrorKind — and a FileOutcome per file, the rows of
//    a manifest (write_manifest).
// Progress goes to the caller's ProgressFn (files done / files); whether it is
// shown (stderr a terminal, no --quiet) is the caller's decision.
#pragma once

#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/work_queue.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <functional>
#include <future>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// A file that failed: the one line saying why (it names the file) and the kind of
// error, as the reader or the job gave it (no_animation: a static mesh).
struct FileFailure {
  std::string file;
  std::string message;
  ErrorKind kind = ErrorKind::other;
};

// What a folder run did with one input (a manifest's "status" column).
enum class FileStatus {
  ok,            // the job ran and succeeded
  exists,        // its output was there and skip_existing was asked
  no_animation,  // found in a folder, holds no animation (a mesh next to the clips): skipped quietly
  failed,        // the job's error, kept as a FileFailure
};
// "ok", "exists", "no-animation", "failed".
std::string_view file_status_name(FileStatus status);

// The clip files of a run: every file named in `inputs` or found in a named folder
// (discover_inputs), then shard `shard_index` of `shard_count` (shard_of). Errors: a
// path that does not exist, no clip file at all, a shard outside 1 ≤ I ≤ N.
Result<std::vector<std::string>> find_run_inputs(const std::vector<std::filesystem::path>& inputs, int shard_index = 1,
                                                 int shard_count = 1);

// Runs task(k) for k = 0 … count − 1 on a work queue of thread_count(threads)
// workers (no more than there are tasks), in that order, with at most `window`
// tasks started and not yet taken, and hands each result to take(k, result) in
// order, on the calling thread. Stops starting tasks once take returns false (the
// tasks started finish first). A task's exception is rethrown from here.
template <class T>
void run_in_order(std::size_t count, unsigned threads, std::size_t window, const std::function<T(std::size_t)>& task,
                  const std::function<bool(std::size_t, T)>& take) {
  std::atomic<bool> stop{false};  // before the queue: its jobs read it until it is gone
  WorkQueue queue(static_cast<unsigned>(std::min<std::size_t>(thread_count(threads), std::max<std::size_t>(1, count))));
  std::deque<std::future<T>> started;  // after the queue: these go first, then the queue finishes its jobs
  std::size_t submitted = 0;
  window = std::max<std::size_t>(1, window);
  try {
    for (std::size_t k = 0; k < count; ++k) {
      for (; submitted < count && submitted < k + window; ++submitted)
        started.push_back(queue.submit([&task, &stop, i = submitted]() -> T { return stop ? T{} : task(i); }));
      T result = started.front().get();
      started.pop_front();
      if (!take(k, std::move(result))) {
        stop = true;
        return;
      }
    }
  } catch (...) {
    stop = true;  // the tasks queued behind it do not start their work
    throw;
  }
}

// A file's place in a folder run: its input and, for a run that writes one file
// per input, where that goes (empty otherwise).
struct RunFile {
  std::string input;
  std::filesystem::path output;
};

// The outcome of one file; a manifest row's first columns.
struct FileOutcome {
  std::string input;
  std::filesystem::path output;
  FileStatus status = FileStatus::ok;
  std::string message;  // the error line of a failed file
  ErrorKind kind = ErrorKind::other;
};

struct FileRunOptions {
  std::vector<std::filesystem::path> named;  // the inputs as named (found_in_directory)
  unsigned threads = 0;                      // the caller's job count: thread_count(threads) workers
  bool skip_existing = false;                // an output already there is not made again
  ProgressFn progress;                       // files done / files, from worker threads
  std::function<void(std::size_t file)> finished;  // file (its index) is done, from a worker thread
  // Each failure in input order, on the calling thread, as soon as it is known.
  std::function<void(const FileFailure&)> on_failure;
};

// A job on files[index]. `threads` is its share of the run's workers (a file run while
// fewer files than workers are left gets the idle ones), to pass on to the library
// calls it makes instead of their own default of one per core. An error fails the
// file; its kind is kept.
using FileJob = std::function<Status(std::size_t index, unsigned threads)>;

struct FileRunReport {
  std::vector<FileOutcome> outcomes;  // one per file, in input order
  std::vector<FileFailure> failures;  // the failed ones, in input order
  unsigned threads = 0;               // workers used
  std::size_t count(FileStatus status) const;
};

// Runs `job` on every file (skip_existing: not on those whose output is a regular
// file already; the output's folder is created first), up to 2 × threads files in
// flight, outcomes in input order.
FileRunReport run_files(const std::vector<RunFile>& files, const FileRunOptions& options, const FileJob& job);

// The manifest of a run, as CSV written atomically: input, output, status, then the
// caller's `columns`, each row's cells from cells(i) (i: the outcome's index).
Status write_manifest(const std::filesystem::path& path, const std::vector<FileOutcome>& outcomes,
                      const std::vector<std::string>& columns,
                      const std::function<std::vector<std::string>(std::size_t)>& cells);

}  // namespace rotinterp
