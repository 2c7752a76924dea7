// The one import layer (private to src/io): every assimp import runs in the
// importer process, rotinterp-import (src/importer/main.cpp), started with
// posix_spawn — no fork of this process, so it is safe with threads and under the
// sanitizers alike — and sends its whole reading back through a pipe in the wire
// format of clip_wire.h. The parent never calls assimp's importers.
#pragma once

#include "clip_wire.h"
#include "rotinterp/io/read.h"

#include <filesystem>

namespace rotinterp::detail {

// The whole read of `path` in this process, assimp included: what the importer
// runs. Never throws: out of memory and exceptions become the outcome's error.
// Warnings are kept in the outcome, not passed to options.on_warning.
wire::ReadOutcome read_in_this_process(const std::filesystem::path& path, const ReadOptions& options);

// read_in_this_process() run by the importer (find_importer()), with
// options.animation, fold_fbx_helpers and cross_check_with_assimp. An error (of
// kind crashed, timed_out, too_large, or other when the importer cannot be
// started) when no whole reading came back; the importer is reaped either way.
Result<wire::ReadOutcome> read_in_importer(const std::filesystem::path& path, const ReadOptions& options);

// main() of the importer executable: `rotinterp-import PROTOCOL PARENT_PID PATH
// ANIMATION FOLD CROSS_CHECK CURVES UNIT` writes the outcome to its standard output.
int importer_main(int argc, char** argv);

}  // namespace rotinterp::detail
