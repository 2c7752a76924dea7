// A character's body (io/record/character_body.h) added to a glTF document our
// writer builds from a clip (gltf_write.cpp): each mesh node a glTF node with its
// mesh (one primitive per material) and its skin over the clip's joints, the
// materials with their base colour and embedded image. Private to src/io/gltf.
//
// Units: the source's numbers times the clip's metres per unit (D). Vertices are
// written where their mesh node's world transform at rest, W, puts them (true size in
// any reader; normals by W's inverse transpose; a mirroring W turns the winding over).
// Inverse bind matrices: the bind pose is the source's — a bone's mesh-to-world at bind
// time, M (its node's world at rest × assimp's offset) — and the joints are ours, J
// (the clip's rest pose, in metres, with no scale: a reader bakes scale into offsets).
// glTF poses a written vertex D·W·v by J(t)·IBM; the source poses v by G(t)·offset, G
// its bone node's world. IBM = J⁻¹·D·M·W⁻¹·D⁻¹ gives J(t)·IBM·D·W·v = D·G(t)·offset·v
// whenever J(t)⁻¹·D·G(t) is the joint's static scale, which is what the clip keeps of
// it; where the bind pose is the rest pose, IBM is J⁻¹, rigid, as glTF exporters write it.
//
// Skins: four weights per vertex, the heaviest, normalized (a vertex with more, or
// whose weights do not sum to 1, is counted in a note); a rigid mesh (no bones)
// under a joint is skinned to that joint with weight 1; one with no joint above it
// is a static node, its vertices already where its world transform puts them.
#pragma once

#include "gltf_document.h"
#include "rotinterp/io/record/character_body.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rotinterp::gltf {

struct BodyKept {
  std::size_t meshes = 0, skins = 0, bones = 0, materials = 0, images = 0;
  std::vector<std::string> notes;  // repairs and losses, one line each
  std::string text() const;        // "1 mesh, 1 skin (32 bones), 1 material kept"
};

// Adds `body` to `doc` (its "nodes" and first scene's "nodes" as gltf_write.cpp
// builds them, joint j being node j), appending to `b`. Refuses a body whose
// indices or numbers are not those of a mesh (a triangle past its vertices, NaN).
Result<BodyKept> add_body(Builder& b, nlohmann::json& doc, const Skeleton& skeleton, double metres,
                          const CharacterBody& body);

}  // namespace rotinterp::gltf
