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
//    key (several takes: one stack and layer per take, each spanning its own keys); `GlobalSettings` with the clip's rate (TimeMode where FBX has a mode for
//    it, else custom + CustomFrameRate), Y up, Z front, X right (right-handed,
//    as BVH), UnitScaleFactor = centimetres per clip unit (100 × metres per unit);
//  * per joint an AnimationCurveNode "R" (and "T" where the joint has a translation
//    track) with one AnimationCurve per axis: by default a key at every key time of the
//    clip (the union over all joints), linear (fbx_frame_curves); or the curves given
//    (encode_fbx_curves: sparse keys, linear or cubic with user tangents, as
//    rotinterp reduce writes them: io/fbx/fbx_reduced.h); Euler angles in degrees in the
//    joint's BVH rotation order (FBX XYZ for joints without one), each the solution
//    nearest the previous key (euler_nearest), so curves never jump by 360°; key
//    times in FBX ticks (46 186 158 000 per second), rounded exactly from the
//    clip's rate where the keys lie on its grid.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"  // kFbxTicksPerSecond: one FBX time unit for reader and writer

#include "rotinterp/clip/sampling.h"
#include "rotinterp/io/files/euler.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

enum class FbxEncoding { binary, ascii };

// One key of a written curve (fbx_write_curves.cpp builds them, fbx_write.cpp
// writes them): linear, or cubic with user slopes in value per second — its own
// right slope and the next key's left slope, as KeyAttrDataFloat holds them
// (io/fbx/fbx_curves.h FbxKey). Left and right slopes that differ make a broken key.
// A key copied from a read file instead keeps its KeyAttrFlags and
// KeyAttrDataFloat as they were (stored_flags non-zero).
struct FbxOutKey {
  std::int64_t ticks = 0;
  float value = 0.0f;
  bool cubic = false;
  float right_slope = 0.0f, next_left_slope = 0.0f;
  std::uint32_t stored_flags = 0;
  std::array<float, 4> stored_data{};
};
using FbxOutCurve = std::vector<FbxOutKey>;

// What is written for one joint: its rotation order and its Lcl Rotation curves
// (degrees) by axis X, Y, Z; Lcl Translation curves (clip units) where it has a
// translation track, else empty.
// A channel without keys has no AnimationCurve: its curve node's default holds it.
// The node's properties are the clip's (the whole local rotation as Lcl Rotation, no
// Pre/PostRotation, the Blender-safe rest translation: fbx_rest.h) unless `node`
// gives the read file's, for curves copied from it.
struct FbxOutNode {
  Vec3 lcl_translation, lcl_rotation;  // static values (degrees)
  Vec3 pre_rotation, post_rotation;    // degrees, XYZ
};
struct FbxOutJoint {
  EulerAxes axes{2, 1, 0};
  std::array<FbxOutCurve, 3> rotation, translation;
  Vec3 rotation_default = Vec3::Zero(), translation_default = Vec3::Zero();  // channels without keys
  bool has_rotation = true;      // an "R" curve node (a character's joint at rest has none: fbx_character.h)
  bool has_translation = false;  // an "T" curve node (any translation channel with keys)
  // Lcl Scaling curves: only a source's own scale written back (io/fbx/fbx_character.h).
  std::array<FbxOutCurve, 3> scaling;
  bool has_scaling = false;  // an "S" curve node
  std::optional<FbxOutNode> node;
};

// The FBX file for `clip` (validated first) as bytes, a linear key at every key
// time of the clip (fbx_frame_curves).
Result<std::string> encode_fbx(const Clip& clip, FbxEncoding encoding);
// The FBX file of `clip`'s skeleton, rate and name with these curves (one per joint,
// some rotation curve with keys) as bytes. Errors: an invalid clip, curves that do
// not match its joints.
Result<std::string> encode_fbx_curves(const Clip& clip, const std::vector<FbxOutJoint>& curves, FbxEncoding encoding);

// One take as written: its AnimationStack's name and its curves (one per joint).
struct FbxOutTake {
  std::string name;
  std::vector<FbxOutJoint> curves;
  // Its AnimationLayer's name: a character's take keeps its source take's, which
  // readers name actions by (Blender: "OBJECT|TAKE" where the two names agree).
  std::string layer = "BaseLayer";
};
// The FBX file of `clip`'s skeleton and unit with these takes (each some rotation
// curve with keys on every joint; every take's joints in the first take's rotation
// orders, and its node properties the first take's), in order, the first the active
// one; each stack spans its own curves' first to last key. TimeMode states `rate`,
// none (0) without one: takes at different rates leave it to each take's key grid.
Result<std::string> encode_fbx_takes(const Clip& clip, const std::vector<FbxOutTake>& takes,
                                     const std::optional<Rate>& rate, FbxEncoding encoding);
// The FBX file of several takes of one skeleton (io/write.h write_clips: named,
// unique, same skeleton, checked there), each keyed from its own t = 0.
Result<std::string> encode_fbx_clips(const std::vector<Clip>& takes, FbxEncoding encoding);

// The writer's curves for `clip` (valid): a linear key at every key time of the clip
// (the union over all joints), Euler angles each nearest the previous key's, in each
// joint's fbx_joint_axes order, or in `axes` (one per joint) where given.
std::vector<FbxOutJoint> fbx_frame_curves(const Clip& clip);
std::vector<FbxOutJoint> fbx_frame_curves(const Clip& clip, const std::vector<EulerAxes>& axes);

// The joint's rotation order as written: its BVH rotation channels where they are
// three different axes, else FBX's default XYZ.
EulerAxes fbx_joint_axes(const Clip& clip, std::size_t joint);

// FBX ticks of clip times: exact on the clip's rate grid (start + round(k·TPS/rate))
// where a time lies on it, else the time rounded to a tick.
std::vector<std::int64_t> fbx_ticks(const std::vector<double>& times, const std::optional<Rate>& rate);

// FBX's TimeMode for an exact rate (FbxTime::EMode: 6 for 30 Hz, 9 for
// 30000/1001, …), or 14 (custom) when FBX has no mode for it.
int fbx_time_mode(std::int64_t rate_num, std::int64_t rate_den);

}  // namespace rotinterp
