// Named temporary files (not installed): the names AtomicOutput gives its temporaries
// (io/files/atomic_file.h, guarantee 3), and the sweep of those a killed process left.
#pragma once

#include <filesystem>
#include <functional>

namespace rotinterp {

// Gives a file a new temporary name next to `target`: `create(name)` makes it (a
// new file, or a link to an unnamed one) and returns false with errno on failure;
// a name taken already (EEXIST) is skipped. The name is registered for the
// interrupt handler before the file exists, so a signal between the two cannot
// leave it behind. Returns the name (with its registration in `slot`), or an empty
// path with the reason in `err`.
std::filesystem::path claim_temp_name(const std::filesystem::path& target, int& slot, int& err,
                                      const std::function<bool(const std::filesystem::path& name)>& create);
// Removes the named temporaries in `dir` that a process no longer running here left
// and that are 10 minutes old (once per directory and process).
void remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace rotinterp
