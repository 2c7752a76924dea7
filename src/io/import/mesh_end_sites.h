// Rigid meshes hanging off animated joints kept as End Sites (scene_to_clip.h):
// a prop or a box whose node sits at its joint's pivot still gives the figure the
// file's shape. Private to src/io.
#pragma once

#include "rotinterp/clip/clip.h"

#include <functional>

struct aiNode;
struct aiScene;

namespace rotinterp {

// For each leaf below `joint_node` (no node below it but assimp's `$AssimpFbx$`
// helpers), reached through helpers only, that carries meshes none of which is
// skinned and that is not itself a joint (`is_joint`): an End Site of `joint` at the
// centre of its meshes' bounding box, in the joint's frame (the transforms of the
// nodes on the way composed), times `scale` (the joint's baked scale), named after
// the leaf. Leaves whose centre is the joint's own pivot add nothing.
void add_mesh_end_sites(const aiScene* scene, const aiNode* joint_node, int joint, double scale,
                        const std::function<bool(const aiNode*)>& is_joint, Skeleton& skeleton);

}  // namespace rotinterp
