// A glTF character in, the same character out (issue 48; STYLE rule 19, a file edit
// is not an export): the source .glb/.gltf document with only its animations
// replaced, written as .glb (or .gltf with its buffer beside it).
//
// Kept as the source has them: nodes (their indices too), meshes, skins with their
// inverse bind matrices, materials, textures, images, samplers, cameras, scenes,
// extensions (declared and used), asset and extras. Replaced: every animation of
// the source; the takes written are the animations, in order, their channels
// targeting the source's nodes (a joint is the node of its name, as the reader
// names nodes: io/gltf/gltf_source.h). A take not written is dropped.
//
// Buffers are rewritten as one: the accessors and buffer views that no animation
// alone uses, packed in their order (each view keeps its offset modulo 4, so every
// accessor keeps the alignment the spec asks of it), then the new animations'.
// Images stored in files beside a .gltf are embedded (their mime type from the
// source or the file's extension); data: URIs stay in the JSON as they are.
//
// Translations are written in the file's numbers: metres (clip units × the clip's
// metres per unit) divided by the uniform scale of the node's ancestors, which the
// reader baked into them (io/import/scene_to_clip.cpp).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/gltf/gltf_write.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {

// What passed through (and what did not), for the one-line summary.
struct GltfKept {
  std::size_t meshes = 0, skins = 0, joints = 0, materials = 0, textures = 0, images = 0, cameras = 0;
  std::size_t embedded_images = 0;   // images read from files beside the source, now in the buffer
  std::size_t dropped_channels = 0;  // the source's scale and morph-weight channels whose values moved
  // "1 mesh, 1 skin (45 joints), 1 material kept", then what was embedded or dropped.
  std::string text() const;
};

// Writes `takes` (valid, read from the glTF/GLB file `source`; each take's joints
// are the nodes of their names, so takes of different joints may be written) to
// `path`, atomically, as the source with its animations replaced. Errors of kind
// file_error::cannot_write are the output's; any other says why the character cannot
// be kept (a joint with no node of its name, or several; a joint node stored as a
// matrix; buffer views with extensions, which point into buffers we would
// rewrite), and nothing is written.
Result<GltfKept> write_gltf_character(const std::vector<const Clip*>& takes, const std::filesystem::path& source,
                                      const std::filesystem::path& path, bool binary, const GltfKeys& keys = {});

}  // namespace rotinterp
