// The words of the summary line that says what a character file kept when only its
// animation was replaced ("1 mesh, 1 skin (45 bones), 1 material kept"): one wording
// for every format's tree edit (io/fbx/fbx_character.h, io/gltf/gltf_character.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rotinterp {

// "1 mesh", "3 meshes".
std::string count_text(std::size_t n, const char* one, const char* many);

// The counted parts joined, then " kept"; a source with none of them says so.
std::string kept_text(const std::vector<std::string>& parts);

// A vertex's skin weights summing to within this of 1 count as normalized: one
// measure for the FBX tree edit, which keeps them, and the glTF body, which normalizes.
inline constexpr double kSkinWeightSumTolerance = 1e-3;
// "60 vertices' skin weights do not sum to 1".
std::string unnormalized_weights_text(std::size_t vertices);

}  // namespace rotinterp
