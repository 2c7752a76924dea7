// What a clip's write may be told, one struct every writer takes (io/write.h picks
// the writer by the path's extension; each format target reads its own fields).
#pragma once

#include <functional>
#include <string>

namespace rotinterp {

struct WriteOptions {
  // Euler order of rotation channels for joints that have no BVH layout (a
  // non-BVH source written as BVH), e.g. "ZXY" (default) — first letter outermost.
  std::string bvh_order = "ZXY";
  // FBX: ASCII FBX 7.4 instead of binary (CLI: --fbx-ascii). Binary is what every
  // current reader takes (Blender reads no ASCII FBX); ASCII is for reading by eye.
  bool fbx_ascii = false;
  // glTF: every track at its own key times (a reduced clip, rotinterp reduce)
  // instead of every joint at the union of the clip's key times.
  bool gltf_own_key_times = false;
  // glTF: rotation samplers CUBICSPLINE with the keys and tangents of the
  // gltf-cubic method (interp/gltf_cubic.h) instead of LINEAR (slerp), and
  // translation samplers CUBICSPLINE with the cubic translation curve's tangents
  // (clip/translation_curve.h) instead of LINEAR. Either needs gltf_own_key_times.
  bool gltf_cubic_rotations = false;
  bool gltf_cubic_translations = false;
  // Receives one-line warnings ("<file>: <what>"), e.g. that the source's meshes and
  // skins are not written; empty = dropped. The CLI prints them on stderr.
  std::function<void(const std::string&)> on_warning;
  // The file the clip was read from, empty if none. An FBX written from an FBX 7
  // file with meshes is that file with only its animation replaced
  // (io/fbx/fbx_character.h), and so is a .glb/.gltf written from a glTF file with
  // meshes (io/gltf/gltf_character.h); on_kept then receives what passed through,
  // one line ("<file>: 1 mesh, 1 skin (32 bones), 1 material kept").
  std::string source;
  std::function<void(const std::string&)> on_kept;
  // Threads for a long BVH's text (core/work_queue.h thread_count: 0 = as many as the
  // machine has; it uses two at most). A caller writing files side by side gives 1.
  unsigned threads = 0;
};

}  // namespace rotinterp
