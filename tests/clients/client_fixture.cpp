#include "client_fixture.h"

#include <cmath>

#include "rotinterp/io/read.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

namespace rotinterp::test {

Reference load_reference(const std::filesystem::path& bvh, const std::vector<std::string>& without_translation) {
  Reference ref;
  auto clip = read_clip(bvh);
  if (!clip) throw std::runtime_error(clip.error());
  ref.clip = *clip;
  for (const std::string& name : without_translation) {
    const int j = ref.clip.skeleton.find(name);
    if (j < 0) throw std::runtime_error("no joint " + name);
    ref.clip.translations[static_cast<std::size_t>(j)].reset();
  }
  const std::size_t frames = ref.clip.frame_count();
  for (std::size_t k = 0; k < frames; ++k)
    ref.frames.push_back(pose_at(ref.clip, ref.clip.start_time() + static_cast<double>(k) * ref.clip.frame_time).position);
  const std::size_t n = ref.clip.skeleton.joints.size();
  std::vector<Quat> rest(n);
  std::vector<Vec3> offsets(n);
  for (std::size_t j = 0; j < n; ++j) {
    rest[j] = ref.clip.skeleton.joints[j].rest_rotation;
    offsets[j] = ref.clip.skeleton.joints[j].offset;
  }
  WorldPose w;
  forward_kinematics(ref.clip.skeleton, rest, offsets, w);
  Vec3 lo = w.position.front(), hi = lo;
  for (const Vec3& p : w.position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  ref.height = (hi - lo).maxCoeff();
  return ref;
}

Residual max_similarity_residual(const Reference& ref, const std::vector<std::string>& names,
                                 const std::vector<std::vector<Vec3>>& positions) {
  if (positions.size() != ref.frames.size()) return {};
  std::vector<int> joint(names.size());
  for (std::size_t b = 0; b < names.size(); ++b) {
    joint[b] = ref.clip.skeleton.find(names[b]);
    if (joint[b] < 0) return {};
  }
  const std::size_t count = names.size() * positions.size();
  Eigen::Matrix3Xd from(3, count), to(3, count);
  std::size_t c = 0;
  for (std::size_t k = 0; k < positions.size(); ++k)
    for (std::size_t b = 0; b < names.size(); ++b, ++c) {
      from.col(static_cast<Eigen::Index>(c)) = positions[k][b];
      to.col(static_cast<Eigen::Index>(c)) = ref.frames[k][static_cast<std::size_t>(joint[b])];
    }
  const Eigen::Matrix4d t = Eigen::umeyama(from, to, true);
  const Eigen::Matrix3Xd mapped = (t.topLeftCorner<3, 3>() * from).colwise() + t.topRightCorner<3, 1>();
  Eigen::Index worst = 0;
  Residual r;
  r.distance = (mapped - to).colwise().norm().maxCoeff(&worst);
  r.joint = names[static_cast<std::size_t>(worst) % names.size()];
  r.frame = static_cast<std::size_t>(worst) / names.size();
  r.scale = std::cbrt(t.topLeftCorner<3, 3>().determinant());
  return r;
}

}  // namespace rotinterp::test
