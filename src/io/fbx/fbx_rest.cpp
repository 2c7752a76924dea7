// The rest translations the FBX writer gives each joint.
#include "fbx_rest.h"

#include <algorithm>

namespace rotinterp {

std::vector<Vec3> fbx_rest_translations(const Clip& clip) {
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  std::vector<Vec3> offsets(n);
  std::vector<Quat> rest(n);
  for (std::size_t j = 0; j < n; ++j) offsets[j] = sk.joints[j].offset, rest[j] = sk.joints[j].rest_rotation;
  WorldPose w;
  forward_kinematics(sk, rest, offsets, w);
  double reach = 0.0;
  for (const Vec3& p : w.position) reach = std::max(reach, p.norm());
  for (const Vec3& o : offsets) reach = std::max(reach, o.norm());
  const double shift = kFbxOffAxisShift * reach;
  for (std::size_t j = 0; j < n; ++j) {
    Vec3& o = offsets[j];
    // On the parent's +Y axis to within the shift: Blender may connect it.
    if (sk.joints[j].parent >= 0 && clip.translations[j] && o.y() > 0.0 && Eigen::Vector2d(o.x(), o.z()).norm() < shift)
      o.x() = shift;
  }
  return offsets;
}

}  // namespace rotinterp
