// An imported assimp scene as a Clip: the conversion the importer runs for every
// format but BVH (read.h says what it does for the user). Private to src/io.
#pragma once

#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <cstddef>
#include <optional>
#include <string>

struct aiAnimation;
struct aiScene;

namespace rotinterp {

// `anim` (one of the scene's animations, at `ticks_per_second`) over the scene's
// node tree into `clip`: joints selected, helper nodes folded (their count added to
// `folded`), keys sampled, static scale baked, the frame rate (the file's own where
// it states one, else detected from the keys), and what the scene says of its
// meshes, frame rate and unit. With `take_ticks`, the take spans [0, take_ticks] on
// the animation's clock (FBX: assimp re-bases each take to its start): keys outside
// it are dropped and both ends are keys. Errors are one line, naming `label`.
Status scene_to_clip(const aiScene* scene, const aiAnimation* anim, double ticks_per_second,
                     std::optional<double> take_ticks, Clip& clip, std::size_t& folded, const Warnings& warn,
                     const std::string& label);

// Whether the scene states its frame rate (FBX GlobalSettings TimeMode, as assimp's
// metadata FrameRate): the animations' ticks per second are then that rate.
bool scene_states_rate(const aiScene* scene);

}  // namespace rotinterp
