// An imported assimp scene as a Clip: the conversion the importer runs for every
// format but BVH (read.h says what it does for the user). Private to src/io.
#pragma once

#include "read_parts.h"
#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <string>

struct aiAnimation;
struct aiScene;

namespace rotinterp {

// `anim` (one of the scene's animations, at `ticks_per_second`) over the scene's
// node tree into `clip`: joints selected, helper nodes folded (their count added to
// `folded`), keys sampled, static scale baked, the frame rate detected, and what
// the scene says of its meshes, frame rate and unit. Errors are one line, naming
// `label`.
Status scene_to_clip(const aiScene* scene, const aiAnimation* anim, double ticks_per_second, Clip& clip,
                     std::size_t& folded, const Warnings& warn, const std::string& label);

}  // namespace rotinterp
