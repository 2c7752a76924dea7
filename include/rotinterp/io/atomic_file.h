// Writing files so that a reader never sees a partial one: write to a temporary
// file in the target's directory, then rename over the target. Temporary files
// still open when the process gets SIGINT/SIGTERM/SIGHUP are removed by the handler
// installed with install_interrupt_cleanup().
#pragma once

#include "rotinterp/core/result.h"

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace rotinterp {

// A temporary sibling of `target` (same directory, so rename is atomic) that is
// deleted unless commit() succeeds. For writers that take a file name (PNG,
// assimp's exporter, plots): write to temp_path(), then commit().
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }
  // Renames the temporary file onto the target. Error names the target.
  Status commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  int slot_ = -1;  // entry in the interrupt-cleanup table
  bool committed_ = false;
};

// A file some writer creates on its own next to a temporary output (assimp's .gltf
// exporter writes its .bin buffer so): removed when this goes out of scope, and by
// the interrupt handler while it lives. Construct it before the writer runs.
class ScopedTempFile {
 public:
  explicit ScopedTempFile(std::filesystem::path path);
  ~ScopedTempFile();
  ScopedTempFile(const ScopedTempFile&) = delete;
  ScopedTempFile& operator=(const ScopedTempFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int slot_ = -1;
};

// Writes `target` through a stream, atomically. `write` returns an error to abort
// (nothing is left behind); a stream failure is reported as an error naming the file.
Status write_file_atomically(const std::filesystem::path& target, const std::function<Status(std::ostream&)>& write);

// Installs SIGINT/SIGTERM/SIGHUP handlers that delete live temporary files, then
// exit with 128 + signal. A signal ignored at the time of the call (nohup) stays
// ignored. Call once from main().
void install_interrupt_cleanup();

}  // namespace rotinterp
