// A character's body from an assimp scene, for ReadOptions::read_body: each node
// with meshes as one BodyMesh (its meshes, one per material, as parts), their bones
// named as the clip's joints, the scene's materials with their base colour and the
// PNG or JPEG image of it (embedded, or the file of that name beside the source).
// Private to src/io/import.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/io/record/character_body.h"

#include <assimp/scene.h>

#include <filesystem>

namespace rotinterp {

// `clip` was read from `scene`: a bone whose node is none of its joints is dropped
// with a note.
CharacterBody scene_body(const aiScene* scene, const Clip& clip, const std::filesystem::path& source);

}  // namespace rotinterp
