// The source's buffers rewritten as one, without its animations (private to
// src/io/gltf; gltf_character.h says what is kept and why).
#pragma once

#include "gltf_container.h"
#include "gltf_document.h"

#include <cstddef>
#include <filesystem>

namespace rotinterp::gltf {

// Removes `doc`'s animations, the accessors only they use and the buffer views only
// those use; packs every other view into one buffer (each at its old offset modulo
// 4), embeds images stored in files under `folder`, and renumbers every reference to
// an accessor or view that the spec and the extensions we know define. Returns the
// buffer, its views and accessors, to which new animations are appended; counts the
// images embedded. Throws std::runtime_error on a file it cannot repack.
Builder repack_without_animations(json& doc, Buffers& buffers, const std::filesystem::path& folder,
                                  std::size_t& embedded_images);

}  // namespace rotinterp::gltf
