// The `source` motion of a glTF 2.0 file: its animation samplers, read from the file
// by our own reader and evaluated as the glTF 2.0 specification defines them
// (Appendix C, "Interpolation"), where assimp keeps only the samplers' key values
// and rotinterp would otherwise interpolate between them.
//
// At glTF time t, with keys t₀ < t₁ < … and u = (t − tₖ)/(tₖ₊₁ − tₖ) in the key
// interval holding t:
//  * STEP: vₖ (the previous key held);
//  * LINEAR: rotations slerp(vₖ, vₖ₊₁, u) on the shortest path (vₖ₊₁ negated where
//    vₖ·vₖ₊₁ < 0, as the spec's reference formula does); other values lerp;
//  * CUBICSPLINE: the Hermite curve of vₖ, vₖ₊₁ with tangents bₖ·Δ (out) and aₖ₊₁·Δ
//    (in), Δ = tₖ₊₁ − tₖ; a rotation is then normalized.
// Before the first key and after the last the first and last values hold (the spec
// clamps). Rotations are unit quaternions; LINEAR and STEP keys are normalized as read
// (as assimp's keys are), CUBICSPLINE values and tangents are taken as stored.
//
// Which node is which joint: assimp names a glTF node by its "name", else
// "nodes_<index>" (its glTF2 importer), and a clip's joints carry those names
// (io/read.h). The clip's clock is glTF's: assimp 5.2.5 does not re-base glTF key
// times (a file keyed from 0.5 s reads with start 0, a key of assimp's own at 0
// holding the first value), so clip time t is glTF time t — up to assimp's float key
// times, which read_file_source (io/source_motion.h) takes as the sampler's keys.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

enum class GltfInterpolation { step, linear, cubic_spline };

// One animation sampler, its accessors decoded to double.
// Rules (validate_gltf_sampler):
//  1. at least one key (the spec asks two of CUBICSPLINE; one is read as a constant);
//  2. times finite and strictly increasing;
//  3. values.size() = keys × width, ×3 for CUBICSPLINE (in-tangent, value, out-tangent
//     per key, in that order), every value finite.
// (2 and 3 are the key rules of io/files/key_checks.h; reading also drops repeated
// keys and refuses rotations of no length there.)
struct GltfSampler {
  GltfInterpolation interpolation = GltfInterpolation::linear;
  std::vector<double> times;   // seconds, glTF time
  std::size_t width = 0;       // components per value: 4 (rotation x, y, z, w as stored) or 3
  std::vector<double> values;  // see rule 3
};
Status validate_gltf_sampler(const GltfSampler& sampler);

// The sampler's value at glTF time t (seconds). width 4 and width 3 respectively.
Quat gltf_rotation_at(const GltfSampler& sampler, double t);
Vec3 gltf_vector_at(const GltfSampler& sampler, double t);

// One animation's rotation and translation channels, per glTF node (-1: none; an
// index into `samplers`). Scale and morph-weight channels are not read.
struct GltfNodeChannels {
  int rotation = -1;
  int translation = -1;
};
struct GltfAnimation {
  std::string name;
  std::vector<GltfSampler> samplers;
  std::vector<GltfNodeChannels> nodes;  // one per node of the file
};
struct GltfAnimations {
  std::vector<std::string> node_names;  // as assimp names them (see above)
  std::vector<GltfAnimation> animations;
  // One warning per sampler whose keys the reader repaired (io/files/key_checks.h K3).
  std::vector<std::string> repairs;
};

// The glTF node of each joint, matched by the name the reader gives it (node_names
// above); -1 where no node, or more than one, carries the joint's name (the clip's
// `#` suffixes do not say which).
std::vector<int> gltf_node_of_joints(const Skeleton& skeleton, const std::vector<std::string>& node_names);

// Reads a .glb or .gltf file's nodes and animations. Buffers come from the GLB's
// binary chunk, data: URIs (base64) or files beside the .gltf given by a relative URI
// that stays in the file's folder; absolute paths, other schemes and `..` are refused
// unless `allow_external_files` (ReadOptions::allow_external_files), and every buffer
// file must be a regular file (io/files/input_file.h). Every accessor read is checked
// against its buffer view and its buffer (count × stride within both) before it is
// read. Errors: one line naming the file (`label`).
Result<GltfAnimations> read_gltf_animations(const std::filesystem::path& path, bool allow_external_files = false);
// The same from the file's bytes; relative buffer URIs resolve in `folder`.
Result<GltfAnimations> parse_gltf_animations(std::string_view bytes, const std::filesystem::path& folder,
                                             const std::string& label, bool allow_external_files = false);

}  // namespace rotinterp
