// An assimp scene's node tree as joints: assimp's helper nodes folded into the
// nodes they belong to, and the nodes that are joints selected.
#include "scene_parts.h"

#include <set>
#include <string_view>
#include <utility>

namespace rotinterp::scene_parts {

namespace {

constexpr const char* kHelperTag = "_$AssimpFbx$_";
constexpr const char* kGeometricTag = "_$AssimpFbx$_Geometric";

bool is_helper(const aiNode* n) { return std::string_view(n->mName.C_Str()).find(kHelperTag) != std::string_view::npos; }

void fold_below(const aiNode* n, int parent, std::vector<const aiNode*> chain, std::vector<NodeRec>& recs,
                std::size_t& folded) {
  if (is_helper(n)) {
    // FBX geometric transforms apply to the node's geometry only: assimp puts
    // GeometricX above the node and GeometricXInverse below it, so they cancel
    // for the children. Dropping both gives the joint its own transform.
    if (std::string_view(n->mName.C_Str()).find(kGeometricTag) == std::string_view::npos) chain.push_back(n);
    ++folded;
    for (unsigned c = 0; c < n->mNumChildren; ++c) fold_below(n->mChildren[c], parent, chain, recs, folded);
    return;
  }
  const int me = static_cast<int>(recs.size());
  recs.push_back(NodeRec{n, parent, std::move(chain)});
  for (unsigned c = 0; c < n->mNumChildren; ++c) fold_below(n->mChildren[c], me, {}, recs, folded);
}

}  // namespace

// The real nodes depth-first, each with its chain of `$AssimpFbx$` helpers: assimp
// splits an FBX node's pivots and pre/post rotations into helper nodes above it,
// and the joint is all of them composed, so world poses stay exact.
std::vector<NodeRec> fold_helpers(const aiNode* root, std::size_t& folded) {
  std::vector<NodeRec> recs;
  fold_below(root, -1, {}, recs, folded);
  return recs;
}

// Joints are the animated nodes, bones, and their ancestors: what moves a mesh or
// is moved. Also transform-only subtrees (no meshes, cameras or lights anywhere
// below): end bones and static joints of a skeleton that nothing animates or skins.
Result<Selection> select_joints(const aiScene* scene, const std::vector<NodeRec>& recs, const Channels& channels,
                                const std::string& label) {
  std::set<std::string> bones;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b) bones.insert(scene->mMeshes[m]->mBones[b]->mName.C_Str());
  std::set<std::string> non_joints;
  for (unsigned c = 0; c < scene->mNumCameras; ++c) non_joints.insert(scene->mCameras[c]->mName.C_Str());
  for (unsigned l = 0; l < scene->mNumLights; ++l) non_joints.insert(scene->mLights[l]->mName.C_Str());
  std::vector<bool> bare(recs.size(), true);  // no mesh/camera/light in the subtree
  for (std::size_t i = recs.size(); i-- > 0;) {
    const aiNode* node = recs[i].node;
    if (node->mNumMeshes > 0 || non_joints.count(node->mName.C_Str())) bare[i] = false;
    for (const aiNode* h : recs[i].chain)
      if (h->mNumMeshes > 0) bare[i] = false;
    if (!bare[i] && recs[i].real_parent >= 0) bare[static_cast<std::size_t>(recs[i].real_parent)] = false;
  }
  Selection out;
  std::vector<bool> keep(recs.size(), false);
  out.animated.assign(recs.size(), false);
  for (std::size_t i = 0; i < recs.size(); ++i) {
    bool a = channels.of(recs[i].node) != nullptr;
    for (const aiNode* h : recs[i].chain) a = a || channels.of(h) != nullptr;
    out.animated[i] = a;
    if (a || bones.count(recs[i].node->mName.C_Str()) || (bare[i] && i > 0))
      for (int k = static_cast<int>(i); k >= 0 && !keep[static_cast<std::size_t>(k)]; k = recs[static_cast<std::size_t>(k)].real_parent)
        keep[static_cast<std::size_t>(k)] = true;
  }
  // The scene root only when it transforms something.
  if (!recs.empty() && keep[0] && !out.animated[0] && recs[0].chain.empty() &&
      to_eigen(recs[0].node->mTransformation).isIdentity(1e-12) && !bones.count(recs[0].node->mName.C_Str()))
    keep[0] = false;
  out.joint_of.assign(recs.size(), -1);
  for (std::size_t i = 0; i < recs.size(); ++i)
    if (keep[i]) {
      out.joint_of[i] = static_cast<int>(out.selected.size());
      out.selected.push_back(i);
    }
  if (out.selected.empty()) return make_error(label + ": the animation moves no node of the scene");
  return out;
}

}  // namespace rotinterp::scene_parts
