// Writing Collada through assimp's exporter (private to src/io; BVH, FBX and
// glTF/GLB have writers of our own).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <filesystem>
#include <optional>
#include <string>

namespace rotinterp {

// assimp exporter id for a lower-case extension with dot (".dae" → "collada");
// nullopt otherwise.
std::optional<std::string> assimp_export_format(const std::string& extension);

// Builds an aiScene from `clip` (a node per joint with its rest transform
// T(offset)·R(rest_rotation), one animation with every joint's keys) and exports
// it atomically. Key times are written in seconds (ticks per second = 1).
Status export_with_assimp(const Clip& clip, const std::filesystem::path& path, const std::string& format);

}  // namespace rotinterp
