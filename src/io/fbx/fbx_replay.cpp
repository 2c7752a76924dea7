// fbx_replay_errors: an FBX file read back and replayed by our reader, against the source's frames.
#include "fbx_replay.h"

#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_transform.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rotinterp {

namespace {

constexpr double kDegrees = 180.0 / kPi;

// The largest displacement of the three virtual vertices at distance d along a
// joint's axes between two world poses.
double shell_distance_between(const Quat& ra, const Vec3& pa, const Quat& rb, const Vec3& pb, double d) {
  double worst = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 v = Vec3::Unit(axis) * d;
    worst = std::max(worst, ((pa + ra * v) - (pb + rb * v)).norm());
  }
  return worst;
}

}  // namespace

Result<FbxReplayErrors> fbx_replay_errors(const std::string& bytes, const Skeleton& skeleton, const DenseClip& source,
                                          const std::vector<std::int64_t>& frame_ticks,
                                          const std::vector<FbxJointBudget>& budgets, double shell_distance,
                                          const std::vector<FbxJointFrame>& joint_frames) {
  const std::string label = "the written FBX";
  Result<FbxDocument> doc = parse_fbx_nodes(bytes, label);
  if (!doc) return doc.failure();
  Result<FbxAnimation> anim = read_fbx_animation(*doc, label);
  if (!anim) return anim.failure();
  if (anim->takes.empty()) return make_error(label + ": no take");
  const FbxTake& take = anim->takes.front();
  const std::map<std::string, FbxNodeLayers> layers = fbx_node_layers(take);
  const std::size_t n = skeleton.joints.size(), frames = frame_ticks.size();
  std::vector<const FbxModel*> model(n, nullptr);
  std::vector<const FbxNodeLayers*> node(n, nullptr);
  for (std::size_t j = 0; j < n; ++j) {
    for (const FbxModel& m : anim->models)
      if (m.name == skeleton.joints[j].name) model[j] = &m;
    if (!model[j]) return make_error(label + ": no node for joint " + skeleton.joints[j].name);
    if (auto it = layers.find(skeleton.joints[j].name); it != layers.end()) node[j] = &it->second;
  }
  const bool shells = std::any_of(budgets.begin(), budgets.end(), [](const FbxJointBudget& b) { return b.shell > 0.0; });

  FbxReplayErrors out;
  out.rotation_deg.assign(n, std::vector<double>(frames, 0.0));
  out.shell.assign(n, std::vector<double>(frames, 0.0));
  out.translation.assign(n, std::vector<double>(frames, 0.0));
  std::vector<Quat> rotation(n), source_rotation(n);
  std::vector<Vec3> translation(n), source_translation(n);
  WorldPose replayed, expected;
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t j = 0; j < n; ++j) {
      const FbxLclValues v = fbx_lcl_values(take, *model[j], node[j], static_cast<double>(frame_ticks[f]));
      rotation[j] = fbx_node_rotation(*model[j], v.rotation);
      translation[j] = joint_frames[j].clip_translation(Vec3(v.translation[0], v.translation[1], v.translation[2]), rotation[j]);
      source_rotation[j] = source.rotation[j][f];
      source_translation[j] = source.translation[j][f];
      out.rotation_deg[j][f] = angular_distance(rotation[j], source_rotation[j]) * kDegrees;
      out.translation[j][f] = (translation[j] - source_translation[j]).norm();
    }
    if (!shells) continue;
    forward_kinematics(skeleton, rotation, translation, replayed);
    forward_kinematics(skeleton, source_rotation, source_translation, expected);
    for (std::size_t j = 0; j < n; ++j)
      if (budgets[j].shell > 0.0)
        out.shell[j][f] = shell_distance_between(replayed.rotation[j], replayed.position[j], expected.rotation[j],
                                                 expected.position[j], shell_distance);
    // A joint's children's positions are its own rotation's doing.
    for (std::size_t c = 0; c < n; ++c)
      if (const int p = skeleton.joints[c].parent; p >= 0 && budgets[static_cast<std::size_t>(p)].shell > 0.0) {
        double& e = out.shell[static_cast<std::size_t>(p)][f];
        e = std::max(e, (replayed.position[c] - expected.position[c]).norm());
      }
  }
  return out;
}

}  // namespace rotinterp
