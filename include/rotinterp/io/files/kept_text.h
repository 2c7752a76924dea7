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

}  // namespace rotinterp
