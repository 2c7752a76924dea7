// Output folders a run creates, and removes again when it does not finish: a
// failed or interrupted run leaves no empty folder behind, while a folder that
// existed before it (with earlier outputs) stays as it was.
#pragma once

#include "rotinterp/core/result.h"

#include <filesystem>

namespace rotinterp {

// Creates `dir` and its missing parents (thread-safe). Each folder created here is
// noted, up to 256 of them, so remove_created_directories() can take it back.
// Error (one line): "<dir>: cannot create the output folder: <reason>".
Status create_output_directories(const std::filesystem::path& dir);

// Removes the folders create_output_directories() made that are empty now, newest
// first (rmdir only: a folder holding a file stays). Async-signal-safe: the
// interrupt handler (io/files/atomic_file.h install_interrupt_cleanup) calls it, and the
// CLI after a failed run.
void remove_created_directories() noexcept;

}  // namespace rotinterp
