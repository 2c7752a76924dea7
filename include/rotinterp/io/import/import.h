// What assimp does for rotinterp, the one target that includes <assimp/…>: the whole
// read of a file in this process (what the importer process runs, io/process), the
// extensions assimp imports, and Collada written through its exporter (BVH, FBX and
// glTF/GLB have writers of our own).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/record/clip_file.h"
#include "rotinterp/io/record/read_options.h"

#include <filesystem>
#include <optional>
#include <set>
#include <string>

namespace rotinterp {

namespace detail {
// The whole read of `path` in this process, assimp included: what the importer
// runs. Never throws: out of memory and exceptions become the outcome's error.
// Warnings are kept in the outcome, not passed to options.on_warning.
ReadOutcome read_in_this_process(const std::filesystem::path& path, const ReadOptions& options);
}  // namespace detail

// The extensions assimp imports, lower case without the dot, and "bvh" (read by our
// own pass). Asked once: only assimp's table, no import.
const std::set<std::string>& assimp_import_extensions();

// Whether read_clip() knows files with this extension ("fbx" or ".FBX"): BVH and
// every format assimp imports.
bool importable_extension(std::string extension);
// The formats read_clip reads, for messages: "bvh, fbx, glb, gltf, dae and 57 more
// formats assimp imports". A file with another extension (a .py, a .txt) is refused
// before any import: "<file>: not a motion file (formats read: …)".
std::string read_formats_text();

// assimp exporter id for a lower-case extension with dot (".dae" → "collada");
// nullopt otherwise.
std::optional<std::string> assimp_export_format(const std::string& extension);

// Builds an aiScene from `clip` (a node per joint with its rest transform
// T(offset)·R(rest_rotation), one animation with every joint's keys) and exports
// it atomically. Key times are written in seconds (ticks per second = 1).
Status export_with_assimp(const Clip& clip, const std::filesystem::path& path, const std::string& format);

}  // namespace rotinterp
