// Our own glTF 2.0 writer (private to src/io): `.glb` (one binary file) or `.gltf`
// (JSON plus a `.bin` buffer named by its content). What it writes:
//  * every joint as a node (name, rest translation and rotation, children); the
//    roots are the scene's nodes;
//  * one skin over all joints, inverse bind matrices from the rest pose, so that
//    readers (Blender) build an armature;
//  * one animation (several takes: one per take, write_clips): per joint a rotation channel (and a translation channel where
//    the joint has a translation track), LINEAR, keys at every key time of the clip
//    (the union over all joints), times as the float nearest start + k/rate.
// Translations are in clip units (glTF means metres; BVH has no unit).
// With GltfKeys::own, each channel has its own key times (the track's own), and
// its sampler may be CUBICSPLINE: rotations with gltf-cubic's keys and tangents,
// translations with the cubic translation curve's — what rotinterp reduce writes.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/record/character_body.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {

// Writes `path`: a .glb, or a .gltf whose buffer goes first, atomically, to
// `<stem>-<hash of its bytes>.bin` beside it, so that runs writing the same .gltf
// at once never pair a .gltf with another run's buffer.
struct GltfKeys {
  bool own_times = false;          // each track at its own key times, not the union
  bool cubic_rotations = false;    // CUBICSPLINE rotations (gltf-cubic), else LINEAR
  bool cubic_translations = false; // CUBICSPLINE translations (Steffen cubic), else LINEAR
};
Status write_gltf(const Clip& clip, const std::filesystem::path& path, bool binary, const GltfKeys& keys = {});
// Several takes of one skeleton (the first's; io/write.h write_clips checks that
// every take has it): one animation per take, named by Clip::name, in order.
Status write_gltf(const std::vector<const Clip*>& takes, const std::filesystem::path& path, bool binary,
                  const GltfKeys& keys = {});

// `takes` with a character's body (read with ReadOptions::read_body from the file
// they were read from): its meshes, skins over the takes' joints, materials and
// images written too (the body's rules: src/io/gltf/gltf_body.h). What passed
// through, for the summary line, and what did not, one line each.
struct GltfBodyWritten {
  std::string kept;                // "1 mesh, 1 skin (32 bones), 1 material kept"
  std::vector<std::string> notes;  // "mesh 'him': 12 vertices have more than 4 weights; …"
};
Result<GltfBodyWritten> write_gltf(const std::vector<const Clip*>& takes, const std::filesystem::path& path, bool binary,
                                   const GltfKeys& keys, const CharacterBody& body);

}  // namespace rotinterp
