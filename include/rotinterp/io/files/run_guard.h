// What a run guards besides each file: its output directory against a second run
// (DirectoryLock) and its inputs against being overwritten (protect_input; every
// AtomicOutput asks check_not_an_input before it commits, io/files/atomic_file.h).
#pragma once

#include "rotinterp/core/result.h"

#include <filesystem>

namespace rotinterp {

// An exclusive lock on an output directory, created if missing (flock on the directory itself, so no
// lock file is left; released when this goes out of scope or the process ends,
// even by SIGKILL), so that two runs writing the same multi-file output cannot mix
// their files.
class DirectoryLock {
 public:
  // Error (one line) when another process holds the lock, or it cannot be taken.
  static Result<DirectoryLock> acquire(const std::filesystem::path& dir);
  DirectoryLock(DirectoryLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  DirectoryLock& operator=(DirectoryLock&&) = delete;
  DirectoryLock(const DirectoryLock&) = delete;
  ~DirectoryLock();

 private:
  explicit DirectoryLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

// Registers an input file: an AtomicOutput whose target is the same file (same
// device and inode, so hard links and symlinks count) refuses to commit.
// A path that does not exist is ignored. Thread-safe.
void protect_input(const std::filesystem::path& input);
// An error ("OUT is the same file as the input IN …") when `output` is a
// registered input; Ok otherwise (also when it does not exist yet).
Status check_not_an_input(const std::filesystem::path& output);

}  // namespace rotinterp
