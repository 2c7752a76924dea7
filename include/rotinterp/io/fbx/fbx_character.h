// An FBX character in, the same character out: the source file's node tree with
// only its animation replaced (issue 48; STYLE rule 19, a file edit is not an
// export).
//
// Every object that is not animation passes through with its properties and
// connections: Geometry, Model, Deformer (Skin, Cluster, BlendShape), Pose,
// Material, Texture, Video (embedded media too), NodeAttribute, the document, the
// global settings and any node we do not know. The AnimationStack, AnimationLayer,
// AnimationCurveNode and AnimationCurve objects are removed with their connections
// and the Takes entries, and the takes written take their place: one stack and
// layer each, connected to the source's own Model objects (by id), their curves in
// each model's own conventions (rotation order, Pre/PostRotation, pivots:
// io/fbx/fbx_transform.h), so that the evaluated local transforms are the clip's.
// Keys keep the source's time axis (clip time t at FBX time take start + t).
//
// What else changes, and why:
//  * GlobalSettings' TimeMode, CustomFrameRate and TimeSpan state the written rate
//    and span; Documents' ActiveAnimStackName the first take;
//  * a binary file is written as binary FBX 7.4 (FBXVersion says 7400, FileId and
//    CreationTime are our writer's, matching its footer); an ASCII source as ASCII;
//  * animated properties other than Lcl Translation, Rotation and Scaling
//    (blend-shape weights, custom attributes) are dropped with the rest of the
//    animation: FbxKept counts those that moved;
//  * repairs of an inconsistent source: connections naming a missing object are
//    dropped, and so is a cluster linked to no model (FbxKept counts them).
// FBX 6.1 sources (animation in Takes, not objects) are not edited: the caller
// writes its skeleton as before.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_write.h"
#include "rotinterp/io/files/euler.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

// The source file, read once: its tree and its models and takes.
struct FbxCharacter {
  std::string label;  // the file as errors name it
  FbxDocument doc;
  FbxAnimation animation;
};

// Reads `path` (binary or ASCII FBX 7.x). Errors: unreadable files, FBX 6.1.
Result<FbxCharacter> read_fbx_character(const std::filesystem::path& path);

// What passed through (and what did not), for the one-line summary.
struct FbxKept {
  std::size_t meshes = 0, skins = 0, bones = 0, blend_shapes = 0, materials = 0, textures = 0, embedded_media = 0,
              bind_poses = 0;
  bool ascii = false;                  // written as ASCII (the source was)
  std::size_t dropped_properties = 0;  // animated properties other than Lcl T/R whose values moved
  std::size_t dropped_connections = 0, dropped_clusters = 0;  // repairs
  std::size_t unnormalized_vertices = 0;  // control points whose skin weights sum to more than 0 but not to 1 (kept)
  // "1 mesh, 1 skin (32 bones), 1 material kept", then what was dropped or repaired.
  std::string text() const;
};

// How one joint's clip motion maps onto its model's Lcl curves, from
// T·Roff·Rp·Rpre·R·Rpost⁻¹·Rp⁻¹·Soff·Sp·S·Sp⁻¹ (io/fbx/fbx_transform.h) with S the
// model's scaling at the take's start: the clip rotation Q = Rpre·R·Rpost⁻¹ and the
// clip translation (T + constant + Q·rotated) · parent_scale, where parent_scale is
// the scale the reader baked into the joint's frame (divided out again here). Our
// own writer's joints (no pre/post rotation, no pivots) have the identity frame.
struct FbxJointFrame {
  EulerAxes axes{2, 1, 0};  // the model's rotation order, outermost first
  Quat pre = Quat::Identity(), post = Quat::Identity();
  Vec3 constant = Vec3::Zero(), rotated = Vec3::Zero();
  double parent_scale = 1.0;
  // Whether the model's static Lcl Translation cannot hold the joint's rest offset
  // (pivots, or another value): the joint is keyed even without a translation track.
  bool keyed_translation = false;
  Quat lcl_rotation(const Quat& q) const { return (pre.conjugate() * q * post).normalized(); }
  Vec3 lcl_translation(const Vec3& t, const Quat& q) const { return t / parent_scale - constant - q * rotated; }
  Vec3 clip_translation(const Vec3& lcl, const Quat& q) const { return (lcl + constant + q * rotated) * parent_scale; }
};

// The take of `source` a clip named `name` was read from: the one of that name, else
// the first; nullptr without takes.
const FbxTake* fbx_character_source_take(const FbxCharacter& source, const std::string& name);

// Each joint's frame and model, in `clip`'s joint order. Errors: a joint with no
// model of its name, or several.
struct FbxCharacterJoints {
  std::vector<FbxJointFrame> frames;
  std::vector<const FbxModel*> models;
};
Result<FbxCharacterJoints> fbx_character_joints(const Clip& clip, const FbxCharacter& source, const FbxTake* take);

// The source's own Lcl Scaling where `take` animates it, keyed at each joint's
// rotation key times (a clip has no scale): written back with the curves.
void keep_source_scaling(std::vector<FbxOutJoint>& curves, const FbxCharacterJoints& joints, const FbxTake* take);

// A take written over the source's take `replaced` (or nullptr): named `name` ("clip"
// if empty), these curves, and the replaced take's layer name where the names agree.
FbxOutTake fbx_character_out_take(const std::string& name, std::vector<FbxOutJoint> curves, const FbxTake* replaced);

// The curves of `clip` (valid, read from `source`) in the conventions of its
// models: a key at every key time of the clip, clip time t at FBX time `take`'s
// start + t (0 without a take); translations with the scale the reader baked into
// them divided out again; the Lcl Scaling `take` animates evaluated at the keys;
// and each joint's model id. Errors: a joint with no model of its name, or several.
struct FbxCharacterTake {
  FbxOutTake take;
  std::vector<std::int64_t> model_ids;  // per joint of the clip
};
Result<FbxCharacterTake> fbx_character_take(const Clip& clip, const FbxCharacter& source, const FbxTake* take);

// A joint that `take` (the source's take replaced, or null) does not animate, whose
// written curves hold its model's static Lcl values, gets no curve node: readers make
// an action per animated object, and the source had none for it (Blender: two
// actions more on Marine_Run, L_FOOT's and R_FOOT's). Exact: the static value holds.
void unkey_resting_joints(FbxCharacterTake& written, const FbxCharacter& source, const FbxTake* take);

// The source's tree with its animation replaced by `takes` (in order, the first the
// active one; their model_ids the source's), at `rate` where they share one, in
// `encoding` (binary: FBX 7.4).
struct FbxCharacterFile {
  std::string bytes;
  FbxKept kept;
};
Result<FbxCharacterFile> encode_fbx_character(const FbxCharacter& source, const std::vector<FbxCharacterTake>& takes,
                                              const std::optional<Rate>& rate, FbxEncoding encoding);

// The file write_clip/write_clips write for takes read from the FBX file `source`
// (io/write.h): each take's curves in the source's conventions, keyed from its
// source take's start (matched by name, else the first), ASCII where asked or where
// the source is. Errors say why the character cannot be kept (the caller then
// writes the skeleton alone, and warns).
Result<FbxCharacterFile> fbx_character_file(const std::vector<Clip>& takes, const std::filesystem::path& source,
                                            bool ascii);

}  // namespace rotinterp
