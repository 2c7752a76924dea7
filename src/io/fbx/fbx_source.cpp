// The `source` motion of an FBX file: joints' local rotations evaluated from its stored
// curves (replay_fbx_rotations at the keys' times for resample; source_motion at any time).
#include "rotinterp/io/fbx/fbx_source.h"

#include "rotinterp/track/sample.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>

namespace rotinterp {

Quat fbx_local_rotation(const FbxTake& take, const FbxJointCurves& joint, double ticks) {
  return fbx_node_rotation(*joint.model, fbx_lcl_values(take, *joint.model, &joint.layers, ticks).rotation);
}



Result<std::vector<FbxJointCurves>> fbx_joint_curves(const Clip& clip, const SourceClip& source,
                                                     const std::vector<std::string>& keep, const std::string& label) {
  const FbxTake& take = source.curves.takes.at(source.take);
  std::map<std::string, FbxNodeLayers> by_node = fbx_node_layers(take);
  std::map<std::string, const FbxModel*> models;
  for (const FbxModel& m : source.curves.models) models.emplace(m.name, &m);

  std::vector<FbxJointCurves> out(clip.skeleton.joints.size());
  std::size_t found = 0;
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::string& name = clip.skeleton.joints[j].name;
    if (std::find(keep.begin(), keep.end(), name) != keep.end()) continue;
    const auto curves = by_node.find(name);
    const auto model = models.find(name);
    if (curves == by_node.end() || model == models.end() || !curves->second.keyed(kFbxRotation)) continue;
    out[j] = {model->second, std::move(curves->second)};
    ++found;
  }
  if (found == 0) return make_error(label + ": --method source: no joint has rotation curves in take '" + take.name + "'");
  return out;
}

double fbx_source_ticks(const SourceClip& source, double t) {
  return static_cast<double>(fbx_take_span(source.curves.takes.at(source.take)).start) +
         t * static_cast<double>(kFbxTicksPerSecond);
}

Result<std::size_t> replay_fbx_rotations(Clip& clip, const SourceClip& source, const std::vector<std::string>& keep,
                                         const std::string& label) {
  auto joints = fbx_joint_curves(clip, source, keep, label);
  if (!joints) return joints.failure();
  const FbxTake& take = source.curves.takes.at(source.take);
  std::size_t replayed = 0;
  for (std::size_t j = 0; j < joints->size(); ++j) {
    const FbxJointCurves& curves = (*joints)[j];
    if (!curves.model) continue;
    RotationTrack& track = clip.rotations[j];
    for (std::size_t k = 0; k < track.times.size(); ++k)
      track.keys[k] = fbx_local_rotation(take, curves, fbx_source_ticks(source, track.times[k]));
    track.make_sign_continuous();
    ++replayed;
  }
  return replayed;
}



}  // namespace rotinterp
