// Leaf meshes under animated joints as End Sites (mesh_end_sites.h).
#include "mesh_end_sites.h"

#include <assimp/scene.h>

#include <cmath>
#include <string>
#include <string_view>

namespace rotinterp {

namespace {

constexpr std::string_view kHelperTag = "_$AssimpFbx$_";
// A centre closer than this to the pivot, relative to the mesh's size, is the pivot.
constexpr double kAtPivot = 1e-6;

bool is_helper(const aiNode* n) { return std::string_view(n->mName.C_Str()).find(kHelperTag) != std::string_view::npos; }

bool only_helpers_below(const aiNode* n) {
  for (unsigned c = 0; c < n->mNumChildren; ++c)
    if (!is_helper(n->mChildren[c]) || !only_helpers_below(n->mChildren[c])) return false;
  return true;
}

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

struct MeshBox {
  Vec3 min = Vec3::Constant(INFINITY), max = Vec3::Constant(-INFINITY);
  bool rigid = true;  // no mesh of the node is skinned
  bool empty() const { return !(min.x() <= max.x()); }
};

MeshBox mesh_box(const aiScene* scene, const aiNode* node) {
  MeshBox box;
  for (unsigned m = 0; m < node->mNumMeshes; ++m) {
    if (node->mMeshes[m] >= scene->mNumMeshes) continue;
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
    if (mesh->mNumBones > 0) box.rigid = false;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const Vec3 p(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
      if (!p.allFinite()) continue;
      box.min = box.min.cwiseMin(p);
      box.max = box.max.cwiseMax(p);
    }
  }
  return box;
}

void visit(const aiScene* scene, const aiNode* node, const Eigen::Matrix4d& to_joint, int joint, double scale,
           const std::function<bool(const aiNode*)>& is_joint, Skeleton& skeleton) {
  const Eigen::Matrix4d here = to_joint * to_eigen(node->mTransformation);
  if (is_helper(node)) {
    for (unsigned c = 0; c < node->mNumChildren; ++c) visit(scene, node->mChildren[c], here, joint, scale, is_joint, skeleton);
    return;
  }
  if (node->mNumMeshes == 0 || is_joint(node) || !only_helpers_below(node)) return;
  const MeshBox box = mesh_box(scene, node);
  if (!box.rigid || box.empty()) return;
  const Vec3 centre = (here * (0.5 * (box.min + box.max)).homogeneous()).head<3>() * scale;
  if (!centre.allFinite() || centre.norm() <= kAtPivot * (box.max - box.min).norm() * scale) return;
  skeleton.end_sites.push_back({joint, centre, node->mName.C_Str()});
}

}  // namespace

void add_mesh_end_sites(const aiScene* scene, const aiNode* joint_node, int joint, double scale,
                        const std::function<bool(const aiNode*)>& is_joint, Skeleton& skeleton) {
  for (unsigned c = 0; c < joint_node->mNumChildren; ++c)
    visit(scene, joint_node->mChildren[c], Eigen::Matrix4d::Identity(), joint, scale, is_joint, skeleton);
}

}  // namespace rotinterp
