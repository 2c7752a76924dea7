// Our own FBX writer (private to src/io): binary FBX 7.4 by default, ASCII FBX 7.4
// on request. What it writes (README "Formats" has the user's view):
//  * every joint as a `Model` of type `LimbNode` with a `NodeAttribute` of type
//    `LimbNode` (TypeFlags "Skeleton"), parented through `Connections` (roots under
//    the scene root), its rest transform as Lcl Translation / Lcl Rotation (a
//    translated joint on its parent's +Y axis moved off it by 1e-5 of the
//    skeleton's reach, so that Blender keeps its motion: fbx_rest.h). Rest
//    rotations are baked: no PreRotation is written, Lcl Rotation carries the whole
//    local rotation, so every reader composes the same transform;
//  * one AnimationStack and AnimationLayer spanning exactly the clip's first to last
//    key; `GlobalSettings` with the clip's rate (TimeMode where FBX has a mode for
//    it, else custom + CustomFrameRate), Y up, Z front, X right (right-handed,
//    as BVH), UnitScaleFactor = centimetres per clip unit (100 × metres per unit);
//  * per joint an AnimationCurveNode "R" (and "T" where the joint has a translation
//    track) with one AnimationCurve per axis and a key at every key time of the
//    clip (the union over all joints), linear; Euler angles in degrees in the
//    joint's BVH rotation order (FBX XYZ for joints without one), each the solution
//    nearest the previous key (euler_nearest), so curves never jump by 360°; key
//    times in FBX ticks (46 186 158 000 per second), rounded exactly from the
//    clip's rate where the keys lie on its grid.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx_curves.h"  // kFbxTicksPerSecond: one FBX time unit for reader and writer

#include <cstdint>
#include <string>

namespace rotinterp {

enum class FbxEncoding { binary, ascii };

// The FBX file for `clip` (validated first) as bytes.
Result<std::string> encode_fbx(const Clip& clip, FbxEncoding encoding);

// FBX's TimeMode for an exact rate (FbxTime::EMode: 6 for 30 Hz, 9 for
// 30000/1001, …), or 14 (custom) when FBX has no mode for it.
int fbx_time_mode(std::int64_t rate_num, std::int64_t rate_den);

}  // namespace rotinterp
