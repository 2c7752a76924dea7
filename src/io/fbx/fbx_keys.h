// One FBX 7.x AnimationCurve's keys as stored (private to src/io/fbx): what
// fbx_curves.cpp reads for every curve it finds in a take's layers.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <string>
#include <vector>

namespace rotinterp {

// The keys of `curve` (an AnimationCurve node) into `c`, with their attributes, the
// curve's Default and its extrapolation. Refused, naming `where`, for arrays of
// differing lengths, attributes that do not cover the keys, and the key rules of
// io/files/key_checks.h; keys it repairs (a repeated key) are dropped with a line in
// `warnings`.
Status read_fbx_curve_keys(const FbxNode& curve, FbxCurve& c, const std::string& where,
                           std::vector<std::string>& warnings);

}  // namespace rotinterp
