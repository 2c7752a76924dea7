// The `source` rotations of an FBX clip: each joint's local rotation evaluated
// from the curves the file stores (io/fbx/fbx_curves.h, fbx_curve_eval.h) instead of
// interpolated between the keys assimp baked from them.
//
// A joint's local rotation is PreRotation · R(Lcl Rotation) · PostRotation⁻¹
// (io/fbx/fbx_transform.h), Lcl Rotation blended over the take's layers, as assimp
// composes the same node (so a replayed key equals the baked one where assimp
// sampled the curves of a one-layer take). RotationActive is not consulted
// (assimp does not either).
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_transform.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {


// A clip read with its curves (ReadOptions::read_curves): the baked clip assimp
// gives, and the take of the selected animation.
struct SourceClip {
  Clip clip;
  FbxAnimation curves;
  std::size_t take = 0;  // index in curves.takes
};


// The node and animated properties of one joint (model nullptr: the joint has
// no rotation curves, or is kept).
struct FbxJointCurves {
  const FbxModel* model = nullptr;
  FbxNodeLayers layers;  // pointing into the source's take
};
// The joint's local rotation at FBX time `ticks`, its layers blended.
Quat fbx_local_rotation(const FbxTake& take, const FbxJointCurves& joint, double ticks);
// Per joint of `clip` (by name), pointing into `source` (keep it alive and in
// place). Joints named in `keep` get none. Errors as replay_fbx_rotations's.
Result<std::vector<FbxJointCurves>> fbx_joint_curves(const Clip& clip, const SourceClip& source,
                                                     const std::vector<std::string>& keep, const std::string& label);
// The FBX time (ticks) of clip time t: the take's span start (fbx_take_span) + t.
double fbx_source_ticks(const SourceClip& source, double t);


// Replaces every rotation key of each joint of `clip` whose node has Lcl Rotation
// curves in `source`'s take with the curves' value at the key's time (clip time t
// is FBX time fbx_source_ticks(t), assimp's re-basing) and makes the tracks
// sign-continuous; joints named in `keep` and joints without rotation curves are
// left as they are. Returns how many joints were replayed. Errors: no joint with
// rotation curves.
Result<std::size_t> replay_fbx_rotations(Clip& clip, const SourceClip& source, const std::vector<std::string>& keep,
                                         const std::string& label);

// The FBX file of `clip` (resampled from `source`: its skeleton, rate and name) in
// which each joint with curves in `source`'s take gets its node's curves back as
// the file stores them — key times, values, interpolation and tangents
// (KeyAttrFlags and KeyAttrDataFloat as read: user, auto, TCB, weighted, …), its
// rotation order and Pre/PostRotation — so that our reader, and the DCC, replay
// the source's own curves (resample --method source -o OUT.fbx without --fps).
// The file keeps the source's time axis (clip time t at FBX time take start + t,
// every joint's keys). Copied per joint, from a one-layer take, where the node has no
// rotation/scaling pivot or offset: Lcl Rotation, and Lcl Translation where the
// joint's translation (its track, else its rest offset) equals the curves at its
// keys (same units); joints in
// `keep`, the rest, and layered takes get a linear key at every frame of `clip`
// as the writer's default. Extrapolation is written as constant. `copied` counts
// the joints whose rotation curves were copied.
struct SourceFbx {
  std::string bytes;
  std::size_t copied = 0;
};
Result<SourceFbx> encode_source_fbx(const Clip& clip, const SourceClip& source, const std::vector<std::string>& keep,
                                    bool ascii, const std::string& label);

}  // namespace rotinterp
