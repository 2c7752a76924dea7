// An FBX node's transform as Maya and MotionBuilder evaluate it from a take: each
// Lcl property's layers blended (io/fbx/fbx_curves.h FbxLayer), then the full local
// transform in FBX's order
//   T · Roff · Rp · Rpre · R · Rpost⁻¹ · Rp⁻¹ · Soff · Sp · S · Sp⁻¹
// where R is the Euler rotation in the node's RotationOrder (FBX names the axes in
// the order they apply: eEulerXYZ is Rz·Ry·Rx) and Rpre, Rpost are XYZ.
//
// Layer blending, layer by layer in the take's order (muted layers skipped):
//  * the take's first layer sets the property (its curves, the curve node's
//    default value where a channel has none); a property it does not animate
//    starts from the node's static value;
//  * an additive layer adds its value times its weight (weight/100, clamped to
//    [0, 1]); an override-passthrough layer blends from the result towards its
//    value by its weight; an override layer replaces the result;
//  * Lcl Rotation in a layer accumulating "by layer" (RotationAccumulationMode 0)
//    blends as a rotation: additive composes result · slerp(1, q, w), passthrough
//    slerps, the Euler angles read (and written back) in XYZ order whatever the
//    node's order, as Maya does; "by channel" (1) blends each Euler angle;
//  * Lcl Scaling in a "multiply" layer (ScaleAccumulationMode 0) blends as powers
//    (additive: result · value^w; passthrough: result^(1−w) · value^w).
// Values in degrees (rotation) and file units; times in FBX ticks.
#pragma once

#include "rotinterp/core/rotation.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/files/euler.h"

#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rotinterp {

// Index of the three Lcl properties in FbxNodeLayers::properties.
inline constexpr std::size_t kFbxTranslation = 0, kFbxRotation = 1, kFbxScaling = 2;
// "Lcl Translation" → kFbxTranslation, …; 3 for any other name.
std::size_t fbx_lcl_index(const std::string& property);

// What one layer of a take holds for one node property.
struct FbxLayerChannels {
  std::size_t layer = 0;
  FbxVec3 defaults{0, 0, 0};                                           // channels without a curve
  std::array<const FbxCurve*, 3> channels{nullptr, nullptr, nullptr};  // X, Y, Z (nullptr: none)
};

// A node's animated properties in a take, each by layer in the take's order.
struct FbxNodeLayers {
  std::array<std::vector<FbxLayerChannels>, 3> properties;  // by kFbxTranslation, …
  // Whether some layer holds a curve with keys on the property (any property: 3).
  bool keyed(std::size_t property = 3) const;
};

// Every node the take animates, by name, pointing into `take` (keep it alive).
std::map<std::string, FbxNodeLayers> fbx_node_layers(const FbxTake& take);

// The node's Lcl Translation, Rotation (degrees) and Scaling at `ticks`, layers
// blended; `node` nullptr: the model's static values.
struct FbxLclValues {
  FbxVec3 translation{0, 0, 0}, rotation{0, 0, 0}, scaling{1, 1, 1};
};
FbxLclValues fbx_lcl_values(const FbxTake& take, const FbxModel& model, const FbxNodeLayers* node, double ticks);

// FBX RotationOrder (0 XYZ, 1 XZY, 2 YZX, 3 YXZ, 4 ZXY, 5 ZYX: innermost axis
// first; XYZ outside 0–5) as io/files/euler.h's outermost-first axes.
EulerAxes fbx_order_axes(int order);

// Euler angles in degrees (X, Y, Z) in FBX rotation order `order` as a rotation.
Quat fbx_euler_rotation(int order, const FbxVec3& degrees);

// Rpre · R(rotation) · Rpost⁻¹: the rotation of the node's local transform.
Quat fbx_node_rotation(const FbxModel& model, const FbxVec3& rotation_degrees);

// The full local transform (parent ← node) of `model` with these Lcl values.
Eigen::Matrix4d fbx_node_matrix(const FbxModel& model, const FbxLclValues& values);

}  // namespace rotinterp
