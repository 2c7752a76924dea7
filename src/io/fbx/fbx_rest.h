// The rest translations our FBX writer writes (private to src/io).
//
// Blender's FBX importer (io_scene_fbx, import_fbx.py: build_skeleton) points each
// bone along its node's local +Y, with its tail at the mean distance of its bone
// children, and CONNECTS a child whose rest head lies on that tail (every
// armature-space coordinate equal within a relative 1e-6). A connected bone
// ignores its location keys, so a translated joint lying on its parent's +Y axis
// loses its motion in Blender (Marine_Run's Spine_0 under Root: its root motion,
// 5.4 mm, 2.5 % of the figure, moved every bone below it).
//
// A joint with translation keys does not need its rest translation for any pose:
// its keys give its translation at every key. So where such a joint lies on its
// parent's +Y axis, the rest translation written is moved off that axis, along the
// parent's +X, by kFbxOffAxisShift × the rest skeleton's reach (largest distance of
// a joint from the origin, clip units): large enough that Blender's relative test
// never holds (1e-5 against its 1e-6), small enough to stay invisible in the rest
// pose. Poses at every key are unchanged; only the rest pose moves, by that much.
#pragma once

#include "rotinterp/clip/clip.h"

#include <vector>

namespace rotinterp {

constexpr double kFbxOffAxisShift = 1e-5;  // of the rest skeleton's reach

// Lcl Translation for each joint of `clip` (validated).
std::vector<Vec3> fbx_rest_translations(const Clip& clip);

}  // namespace rotinterp
