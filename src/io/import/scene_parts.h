// The steps of scene_to_clip() (scene_to_clip.cpp) with files of their own: the
// scene's node tree as joints (scene_joints.cpp) and each joint's keys, key times and
// frame rate (scene_keys.cpp). Private to src/io.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"

#include <assimp/scene.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::scene_parts {

inline Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

// The animation's channels by node name (the first where names repeat).
class Channels {
 public:
  explicit Channels(const aiAnimation* anim) {
    for (unsigned c = 0; c < anim->mNumChannels; ++c) by_name_.emplace(anim->mChannels[c]->mNodeName.C_Str(), anim->mChannels[c]);
  }
  const aiNodeAnim* of(const aiNode* n) const {
    const auto it = by_name_.find(n->mName.C_Str());
    return it == by_name_.end() ? nullptr : it->second;
  }

 private:
  std::map<std::string, const aiNodeAnim*> by_name_;
};

// ---- joints (scene_joints.cpp) ----------------------------------------------------

// A node that is not an assimp helper, with the helpers above it.
struct NodeRec {
  const aiNode* node = nullptr;
  int real_parent = -1;              // index in the list of the nearest non-helper ancestor
  std::vector<const aiNode*> chain;  // helper nodes between real_parent and node, top first
};

// The real nodes depth-first, each with its chain of `$AssimpFbx$` helpers: assimp
// splits an FBX node's pivots and pre/post rotations into helper nodes above it,
// and the joint is all of them composed, so world poses stay exact.
std::vector<NodeRec> fold_helpers(const aiNode* root, std::size_t& folded);

struct Selection {
  std::vector<std::size_t> selected;  // the joints' indices among the nodes, in order
  std::vector<int> joint_of;          // per node: its joint, or −1
  std::vector<bool> animated;         // per node: a channel moves it or a helper of its chain
};

// Joints are the animated nodes, bones, and their ancestors: what moves a mesh or
// is moved. Also transform-only subtrees (no meshes, cameras or lights anywhere
// below): end bones and static joints of a skeleton that nothing animates or skins.
Result<Selection> select_joints(const aiScene* scene, const std::vector<NodeRec>& recs, const Channels& channels,
                                const std::string& label);

// ---- keys (scene_keys.cpp) --------------------------------------------------------

// Translation, rotation, scale of an affine matrix (no shear assumed).
struct Trs {
  Vec3 t = Vec3::Zero();
  Quat r = Quat::Identity();
  Vec3 s = Vec3::Ones();
};

// A take's span in ticks, on the animation's clock. FBX declares one per take
// (LocalStart..LocalStop, else its keys' span); assimp re-bases the keys to its start,
// so it is [0, mDuration] there. Keys outside it only shape the curves inside it.
struct TickSpan {
  double lo = 0.0, hi = 0.0;
};

struct KeyTimes {
  std::vector<double> all;   // every key of every channel within the span, ticks
  double first = 0.0;        // the span's start, else the first key: where unanimated joints get theirs
  double last = 0.0;         // the last key within the span
  std::size_t distinct = 0;  // distinct times in `all`
  std::optional<TickSpan> span;
  bool whole_ticks = false;  // every key on a whole tick (within kWholeTickTolerance)
};

// The union over all channels (within `span` where given): unanimated joints and
// the frame rate need it.
Result<KeyTimes> key_times(const aiAnimation* anim, const std::optional<TickSpan>& span, const std::string& label);

struct JointKeys {
  Trs rest;                   // the chain's static transforms composed
  std::vector<double> ticks;  // distinct key times of the chain's channels in the span, and its ends (or the first key)
  std::vector<Trs> keys;      // the chain's local transform at each tick
};

// A joint's keys at the union of its chain's key times: a helper and its bone may
// be keyed at different times, and the joint is their product at every one of them.
// With a span, keys outside it are dropped and its two ends are keys.
JointKeys sample_joint(const NodeRec& rec, bool animated, const Channels& channels, const KeyTimes& times);

// Seconds per frame, 0 if the keys lie on no grid. Ticks at a frame rate (FBX, .x)
// give it directly; float seconds (glTF) and fine ticks (Collada) the step of the
// keys' uniform grid, snapped to an integer or NTSC rate within the tolerance.
double detect_frame_time(const KeyTimes& times, double tps);

}  // namespace rotinterp::scene_parts
