// Reading clips from files: every format assimp imports (BVH, FBX, glTF/GLB,
// Collada, …), with BVH-specific care (channel layout and exact Frame Time from
// the file's header, validation assimp does not do).
//
// What the reader does (README "Formats" has the user's view):
//  * BVH: our own pass (io/bvh/bvh.h) validates the whole file first (before assimp
//    sees it: NaN/inf values, Frame Time ≤ 0 and short data fail fast) and gives the
//    layout, End Sites, exact Frame Time and every channel value in double precision,
//    including the position channels assimp drops (any layout but exactly 6
//    channels). Key k is at k·Frame Time. assimp is not needed for BVH; with
//    ReadOptions::cross_check_with_assimp it also imports the file and must agree
//    (joints, frames, rotations within float precision, else a warning).
//  * Other formats: joints are the animated nodes, the bones of meshes and all
//    their ancestors (the scene root only when its transform is not the identity);
//    assimp's `$AssimpFbx$` helper nodes are folded into their bone (static and
//    animated transforms composed, keys at the union of their times) so world poses
//    are exact. A uniform static scale on a node is baked into the translations of
//    its descendants; other scale is ignored with a warning. A leaf node carrying
//    unskinned meshes under an animated joint becomes an End Site of that joint at
//    its meshes' bounding-box centre (a prop or box hanging off its pivot).
//  * Every key is normalized and the track made sign-continuous.
//  * The clip's unit (Clip::unit) is settled here, once: declared by the file, given
//    (ReadOptions::unit) or inferred (clip/units.h).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/process/importer.h"
#include "rotinterp/io/record/read_options.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace rotinterp {


// Reads one animation of `path` into a validated Clip (tracks sign-continuous).
// Errors are one line and name the file; their kind (core/result.h) says whether
// the file was unreadable, held no animation, or made the importer crash, run too
// long or answer too much. Skeletons nested deeper than kMaxJointDepth (io/bvh/bvh.h)
// are refused in every format.
Result<Clip> read_clip(const std::filesystem::path& path, const ReadOptions& options = {});



}  // namespace rotinterp
