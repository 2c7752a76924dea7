// What an interrupted run takes back (io/files/atomic_file.h, guarantee 4): on
// SIGINT/SIGTERM/SIGHUP the named temporaries still open and the output folders the
// run created (io/files/output_dirs.h), if still empty, are removed before it exits.
#pragma once

namespace rotinterp {

// Installs SIGINT/SIGTERM/SIGHUP handlers that delete live temporary files and the
// output folders the run created that are still empty (io/files/output_dirs.h), write
// `line` (when given, a static string: "rotinterp: interrupted\n") on stderr, then
// exit with 128 + signal. A signal ignored at the time of the call (nohup) stays
// ignored. Call once from main().
void install_interrupt_cleanup(const char* line = nullptr);
// Deletes the live named temporary files now (async-signal-safe): for a handler
// that ends the process another way (an uncaught out-of-memory).
void remove_live_temporaries() noexcept;

}  // namespace rotinterp
