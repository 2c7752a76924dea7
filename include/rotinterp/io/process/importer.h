// The importer process (io/process): every assimp import runs in an
// importer process, rotinterp-import (src/importer/main.cpp), started with
// posix_spawn — no fork of this process, so it is safe with threads and under the
// sanitizers alike. Each thread keeps its importer across files: a request in, the
// whole reading back in the wire format of clip_wire.h (import_protocol.h frames
// both). The parent never calls assimp's importers.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/record/clip_file.h"
#include "rotinterp/io/record/read_options.h"

#include <sys/types.h>

#include <filesystem>

namespace rotinterp {

// The importer executable read_clip() starts for assimp imports, found in this
// order: the environment variable ROTINTERP_IMPORTER (a path); next to the running
// executable or to the library holding read_clip (same directory, or the
// installed libexec directory relative to bin/ or lib/); the path it was built at.
// An error when none is an executable file.
Result<std::filesystem::path> find_importer();

namespace detail {


// read_in_this_process() (io/import/import.h) run by the calling thread's importer (find_importer()),
// with options.animation, fold_fbx_helpers, cross_check_with_assimp, read_curves
// and unit. The importer is started on the thread's first read and kept for the
// next; it is replaced after a crash, a timeout, a reply past max_import_bytes,
// or once its resident memory passes a bound. An error (of kind crashed,
// timed_out, too_large, or other when the importer cannot be started) when no
// whole reading came back. A crash in an importer that had read other files is
// retried once in a fresh one, so that only the file that crashes it fails.
Result<ReadOutcome> read_in_importer(const std::filesystem::path& path, const ReadOptions& options);

// main() of the importer executable: `rotinterp-import VERSION PARENT_PID` answers
// requests on its standard input with replies on its standard output until the
// input ends.
int importer_main(int argc, char** argv);

// For tests: how many importers this process has started, and the calling
// thread's running importer (-1 when it has none).
long importers_started();
pid_t importer_of_this_thread();

}  // namespace detail

}  // namespace rotinterp
