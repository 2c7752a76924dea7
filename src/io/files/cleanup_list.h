// The one list of what an interrupted or failed run takes back: live temporary files
// (io/files/atomic_file.h) and the output folders the run created (io/files/output_dirs.h). The
// paths are kept as fixed C strings, so a signal handler can remove them without
// allocating.
#pragma once

#include <string>

namespace rotinterp::cleanup {

enum class Kind {
  file,    // unlinked; registered while live, dropped once it is the target's
  folder,  // removed if empty; stays registered for the run
};

// Notes `path`; returns its slot, or -1 when the list is full (256 of each kind) or
// the path too long (it is then simply not taken back). Thread-safe.
int add(const std::string& path, Kind kind);
// Forgets a slot add() returned (-1 is ignored).
void drop(int slot);
// Removes every registered path of `kind` (async-signal-safe): files unlinked;
// folders rmdir-ed (only empty ones go), innermost first, so a created chain a/b/c
// goes whole.
void remove_all(Kind kind) noexcept;

}  // namespace rotinterp::cleanup
