// source_truth: eval's reference from the FBX curves the clip was baked from.
#include "rotinterp/eval/source_truth.h"

#include "rotinterp/io/fbx_source.h"
#include "rotinterp/track/sample.h"

#include <memory>

namespace rotinterp {

Result<TruthFn> source_truth(const std::string& clip_file, const Clip& clip) {
  ReadOptions options;
  options.animation = clip.name;
  auto read = read_source_clip(clip_file, options);
  if (!read) {
    options.animation.clear();  // a clip named after its file: the first take
    read = read_source_clip(clip_file, options);
  }
  if (!read) return read.failure();
  auto source = std::make_shared<const SourceClip>(std::move(*read));
  const std::size_t n = clip.skeleton.joints.size();
  bool same = source->clip.skeleton.joints.size() == n;
  for (std::size_t j = 0; same && j < n; ++j) same = source->clip.skeleton.joints[j].name == clip.skeleton.joints[j].name;
  if (!same) return make_error(clip_file + ": --truth source: the second read of the file has other joints");
  auto curves = fbx_joint_curves(clip, *source, {}, clip_file);
  if (!curves) return curves.failure();
  auto joints = std::make_shared<const std::vector<FbxJointCurves>>(std::move(*curves));
  auto baked = std::make_shared<const Clip>(clip);
  return TruthFn([source, joints, baked](double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation) {
    const std::size_t count = baked->skeleton.joints.size();
    rotation.resize(count);
    translation.resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      const FbxJointCurves& c = (*joints)[j];
      rotation[j] = c.model ? fbx_local_rotation(source->curves.takes.at(source->take), c, fbx_source_ticks(*source, t))
                            : sample_rotation(baked->rotations[j], t);
      const auto& track = baked->translations[j];
      translation[j] = track ? sample_translation(*track, t) : baked->skeleton.joints[j].offset;
    }
  });
}

}  // namespace rotinterp
