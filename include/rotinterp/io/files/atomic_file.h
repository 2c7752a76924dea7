// Writing files so that a reader never sees a partial one, and a failure never
// costs the previous good file: write to a temporary file in the target's
// directory, check every write, fsync, then rename over the target.
//
// Guarantees (README "Robustness"):
//  1. Every write, the fsync and the close are checked; on any failure (a full
//     disk) commit() is refused, the target keeps its previous content and the
//     temporary is removed.
//  2. Replacing a file keeps its mode (and owner and group, where permitted); a new
//     file gets 0666 & ~umask.
//  3. Unnamed temporaries (O_TMPFILE) where the filesystem has them, so even a
//     SIGKILL leaves nothing; named ones (".rotinterp.PID.N.tmp.EXT", short, so
//     targets of up to 255 bytes work) elsewhere and for writers that open a path.
//     A named temporary whose process is gone and that is 10 minutes old is removed
//     by the next run that writes into that directory.
//  4. SIGINT/SIGTERM/SIGHUP remove the named temporaries still open and the
//     output folders the run created, if still empty (io/files/interrupt_cleanup.h).
//  5. An output that is the same file (device and inode: links count) as a
//     registered input (protect_input(), io/files/run_guard.h) is refused.
//
// Test seam: with ROTINTERP_TEST_FAULT_AT=N in the environment, the Nth checked
// operation of the process (a write, an fsync or a close, counted from 1) fails
// with ENOSPC, so tests can make every writer fail at every point.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/files/run_guard.h"  // commit() refuses a registered input (5.)

#include <cstddef>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace rotinterp {

enum class TempKind {
  unnamed,  // O_TMPFILE where available (nothing to leave behind), else named
  named,    // a file with a path, for writers that open one (assimp's Collada exporter)
};

// A temporary sibling of `target` (same directory, so rename is atomic) that is
// deleted unless commit() succeeds. The target's missing folders are created first
// (io/files/output_dirs.h: a failed run takes them back), so every writer makes them.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path target, TempKind kind = TempKind::named);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // Empty for an unnamed temporary.
  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }
  // The first error so far (creating the temporary, a write, the sync), if any.
  Status status() const;
  // Appends bytes to the temporary (all of them, or an error naming the target).
  Status write(const void* data, std::size_t size);
  // fsync, then the target's mode and owner. Called by commit(); call it early to
  // finish several outputs before committing them together (commit_together).
  Status finish();
  // finish(), then renames the temporary onto the target. Error names the target.
  Status commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  int fd_ = -1;
  int slot_ = -1;  // entry in the interrupt-cleanup table
  std::string error_;
  bool finished_ = false;
  bool committed_ = false;
};

// Commits finished outputs one after the other with SIGINT/SIGTERM/SIGHUP held
// back, so an interrupt sees all of them committed or none (a signal arriving
// meanwhile is handled afterwards). Stops at the first failure.
Status commit_together(const std::vector<AtomicOutput*>& outputs);

// Writes `data` to `fd` in full, retrying short writes and EINTR. Error:
// "<label>: cannot write: <reason>". Counts as checked operations for the seam.
Status checked_write(int fd, const void* data, std::size_t size, const std::string& label);
// fsync(fd) (when `sync`), then close(fd), both checked; the fd is closed either way.
Status checked_close(int fd, bool sync, const std::string& label);

// Writes `target` through a stream, atomically (an unnamed temporary). `write`
// returns an error to abort (nothing is left behind); a failed write is reported as
// an error naming the file.
Status write_file_atomically(const std::filesystem::path& target, const std::function<Status(std::ostream&)>& write);
// The same, written into `out` without committing it (see commit_together).
Status write_to(AtomicOutput& out, const std::function<Status(std::ostream&)>& write);

}  // namespace rotinterp
