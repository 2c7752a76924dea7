// replay_fbx_rotations: joints' local rotations evaluated from the FBX file's
// stored curves at the keys' times (the `source` method of resample).
#include "rotinterp/io/fbx_source.h"

#include "rotinterp/io/euler.h"
#include "rotinterp/io/fbx_curve_eval.h"
#include "rotinterp/io/info.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace rotinterp {

namespace {

constexpr double kRadiansPerDegree = kPi / 180.0;

// FBX RotationOrder (0 XYZ, 1 XZY, 2 YZX, 3 YXZ, 4 ZXY, 5 ZYX: innermost axis
// first) as io/euler.h's outermost-first axes.
EulerAxes fbx_order_axes(int order) {
  static const char* names[] = {"XYZ", "XZY", "YZX", "YXZ", "ZXY", "ZYX"};
  const char* name = names[order >= 0 && order < 6 ? order : 0];
  return {name[2] - 'X', name[1] - 'X', name[0] - 'X'};
}

Quat euler_degrees(const EulerAxes& axes, const FbxVec3& xyz) {
  const Vec3 angles(xyz[static_cast<std::size_t>(axes[0])], xyz[static_cast<std::size_t>(axes[1])],
                    xyz[static_cast<std::size_t>(axes[2])]);
  return euler_to_quat(axes, angles * kRadiansPerDegree);
}

// Lcl Rotation curves of one node, per channel, and the layers they lie in.
struct NodeCurves {
  std::array<const FbxCurve*, 3> channels{nullptr, nullptr, nullptr};
  std::vector<std::size_t> layers;
};

}  // namespace

bool is_source_method(const std::string& name) {
  const std::string want = kSourceMethodName;
  return name.size() == want.size() &&
         std::equal(name.begin(), name.end(), want.begin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

Quat fbx_local_rotation(const FbxModel& model, const std::array<const FbxCurve*, 3>& channels, double ticks) {
  FbxVec3 angles = model.rotation;
  for (std::size_t c = 0; c < 3; ++c)
    if (channels[c]) angles[c] = evaluate_fbx_curve(*channels[c], ticks);
  const EulerAxes xyz = fbx_order_axes(0);
  const Quat q = euler_degrees(xyz, model.pre_rotation) * euler_degrees(fbx_order_axes(model.rotation_order), angles) *
                 euler_degrees(xyz, model.post_rotation).conjugate();
  return q.normalized();
}

Result<SourceClip> read_source_clip(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  ReadOptions with_curves = options;
  with_curves.read_curves = true;
  Result<ClipFileInfo> info = inspect_clip(path, with_curves);
  if (!info) return info.failure();
  if (!info->curves)
    return make_error(label + ": --method source replays FBX curves; this is a '" + info->format +
                      "' file (use an interpolator, e.g. clamped)");
  const FbxTake* take = selected_take(*info);
  if (!take) return make_error(label + ": --method source: the file has no animation stack, so no curves to replay");
  SourceClip out;
  out.take = static_cast<std::size_t>(take - info->curves->takes.data());
  out.clip = std::move(info->clip);
  out.curves = std::move(*info->curves);
  return out;
}

Result<std::vector<FbxJointCurves>> fbx_joint_curves(const Clip& clip, const SourceClip& source,
                                                     const std::vector<std::string>& keep, const std::string& label) {
  const FbxTake& take = source.curves.takes.at(source.take);
  std::map<std::string, NodeCurves> by_node;
  for (const FbxCurve& c : take.curves) {
    if (c.property != "Lcl Rotation" || c.channel < 'X' || c.channel > 'Z') continue;
    if (c.layer < take.layers.size() && take.layers[c.layer].mute) continue;
    NodeCurves& node = by_node[c.node];
    if (std::find(node.layers.begin(), node.layers.end(), c.layer) == node.layers.end()) node.layers.push_back(c.layer);
    node.channels[static_cast<std::size_t>(c.channel - 'X')] = &c;
  }
  std::map<std::string, const FbxModel*> models;
  for (const FbxModel& m : source.curves.models) models.emplace(m.name, &m);

  std::vector<FbxJointCurves> out(clip.skeleton.joints.size());
  std::size_t found = 0;
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::string& name = clip.skeleton.joints[j].name;
    if (std::find(keep.begin(), keep.end(), name) != keep.end()) continue;
    const auto curves = by_node.find(name);
    const auto model = models.find(name);
    if (curves == by_node.end() || model == models.end()) continue;
    if (curves->second.layers.size() > 1)
      return make_error(label + ": --method source: joint '" + name + "' is animated in " +
                        std::to_string(curves->second.layers.size()) + " layers of take '" + take.name +
                        "'; blending layers is not evaluated yet");
    out[j] = {model->second, curves->second.channels};
    ++found;
  }
  if (found == 0) return make_error(label + ": --method source: no joint has rotation curves in take '" + take.name + "'");
  return out;
}

double fbx_source_ticks(const SourceClip& source, double t) {
  return static_cast<double>(source.curves.takes.at(source.take).start) + t * static_cast<double>(kFbxTicksPerSecond);
}

Result<std::size_t> replay_fbx_rotations(Clip& clip, const SourceClip& source, const std::vector<std::string>& keep,
                                         const std::string& label) {
  auto joints = fbx_joint_curves(clip, source, keep, label);
  if (!joints) return joints.failure();
  std::size_t replayed = 0;
  for (std::size_t j = 0; j < joints->size(); ++j) {
    const FbxJointCurves& curves = (*joints)[j];
    if (!curves.model) continue;
    RotationTrack& track = clip.rotations[j];
    for (std::size_t k = 0; k < track.times.size(); ++k)
      track.keys[k] = fbx_local_rotation(*curves.model, curves.channels, fbx_source_ticks(source, track.times[k]));
    track.make_sign_continuous();
    ++replayed;
  }
  return replayed;
}

}  // namespace rotinterp
