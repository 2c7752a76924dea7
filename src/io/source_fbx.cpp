// An FBX file's own curves read through the entry point (inspect_clip with
// read_curves), and their replay as a FileSource (io/source_motion.h); the replay
// itself is the FBX target's (io/fbx/fbx_source.h).
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/track/sample.h"

#include <memory>

namespace rotinterp {

Result<SourceClip> read_source_clip(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  ReadOptions with_curves = options;
  with_curves.read_curves = true;
  Result<ClipFileInfo> info = inspect_clip(path, with_curves);
  if (!info) return info.failure();
  return source_clip_of(std::move(*info), label);
}

Result<SourceClip> source_clip_of(ClipFileInfo&& info, const std::string& label) {
  if (!info.curves)
    return make_error(label + ": --method source replays FBX curves; this is a '" + info.format +
                      "' file (use an interpolator, e.g. clamped)");
  const FbxTake* take = selected_take(info);
  if (!take) return make_error(label + ": --method source: the file has no animation stack, so no curves to replay");
  SourceClip out;
  out.take = static_cast<std::size_t>(take - info.curves->takes.data());
  out.clip = std::move(info.clip);
  out.curves = std::move(*info.curves);
  return out;
}

Result<FileSource> fbx_file_source(std::shared_ptr<const SourceClip> source, const std::string& label) {
  auto curves = fbx_joint_curves(source->clip, *source, {}, label);
  if (!curves) return curves.failure();
  auto joints = std::make_shared<const std::vector<FbxJointCurves>>(std::move(*curves));
  FileSource out;
  out.clip = source->clip;
  for (const FbxJointCurves& c : *joints) out.own.push_back(c.model != nullptr);
  out.replays = "the file's curves";
  out.fbx = source;
  out.motion = [source, joints](std::size_t j, double t) {
    const FbxJointCurves& c = (*joints)[j];
    return c.model ? fbx_local_rotation(source->curves.takes.at(source->take), c, fbx_source_ticks(*source, t))
                   : sample_rotation(source->clip.rotations[j], t);
  };
  return out;
}

Result<SourceMotion> source_motion(std::shared_ptr<const SourceClip> source, const std::string& label) {
  auto file = fbx_file_source(std::move(source), label);
  if (!file) return file.failure();
  return file->motion;
}

}  // namespace rotinterp
