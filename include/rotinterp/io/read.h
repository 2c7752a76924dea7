// Reading clips from files: every format assimp imports (BVH, FBX, glTF/GLB,
// Collada, …), with BVH-specific care (channel layout and exact Frame Time from
// the file's header, validation assimp does not do).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <filesystem>
#include <string>

namespace rotinterp {

struct ReadOptions {
  // Which animation: its name, or its index as a decimal string; empty = the first.
  std::string animation;
};

// Reads one animation of `path` into a validated Clip (tracks sign-continuous).
// Errors are one line and name the file.
Result<Clip> read_clip(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace rotinterp
