// rotinterp info CLIP --curves [--sample HZ] [--json]: the FBX curves of the
// selected take as the file stores them (cmd_info.cpp reads, this prints).
#pragma once

#include "rotinterp/io/info.h"

#include <string>

namespace rotinterp::cli {

// Prints the curves of `info` (read with ReadOptions::read_curves) as text or
// JSON; sample_hz > 0 adds the evaluated values at k/sample_hz s. Returns the exit
// code (an error when the file is not FBX).
int print_info_curves(const std::string& path, const ClipFileInfo& info, double sample_hz, bool json);

}  // namespace rotinterp::cli
