// FBX files older than 7.0 (FBX 6.1), read into a clip by our own FBX reader:
// assimp 5.2.5 refuses them ("FBX-DOM unsupported, old format version"). Private
// to src/io; the importer process runs it like every FBX read.
#pragma once

#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/io/record/clip_file.h"

#include <filesystem>
#include <string>

namespace rotinterp {

// Whether `path` holds an FBX document older than 7.0: a binary header version
// below 7000, or an ASCII "; FBX 6." / "FBXVersion: 6…" near its start.
bool is_legacy_fbx(const std::filesystem::path& path);

// The selected take (ReadOptions::animation: name or index) as a clip:
//  * joints: the models the take animates, every model that is not a mesh,
//    camera or light, and their ancestors; parents first, in file order;
//  * each joint's offset and rest rotation from its static Properties60 values
//    through the full FBX transform (io/fbx_transform.h), scale left out;
//  * keys at every frame of the take (LocalTime) at the file's rate
//    (GlobalSettings TimeMode / CustomFrameRate), t = 0 at the take's start as
//    assimp re-bases 7.x takes; without a stated rate, at the union of the
//    joint's key times. Rotation keys for every animated joint, translation
//    tracks where the translation moves; unanimated joints get one key.
//  * the unit from UnitScaleFactor; source meshes: the Mesh models.
// With ReadOptions::read_curves, info.curves holds the file's curves too. Errors
// are one line naming the file (and the node, for malformed takes).
Status read_legacy_fbx(const std::filesystem::path& path, const ReadOptions& options, ClipFileInfo& info,
                       const Warnings& warn);

}  // namespace rotinterp
