// source_truth: eval's reference from the file's own motion (io/source_motion.h): FBX
// curves, glTF animation samplers, BVH frames.
#include "rotinterp/eval/source_truth.h"

#include "rotinterp/io/source_motion.h"
#include "rotinterp/track/sample.h"

#include <memory>

namespace rotinterp {

Result<TruthFn> source_truth(const std::string& clip_file, const Clip& clip, bool allow_external_files) {
  ReadOptions options;
  options.animation = clip.name;
  options.allow_external_files = allow_external_files;
  auto read = read_file_source(clip_file, options);
  if (!read) {
    options.animation.clear();  // a clip named after its file: the first animation
    read = read_file_source(clip_file, options);
  }
  if (!read) return read.failure();
  auto source = std::make_shared<const FileSource>(std::move(*read));
  const std::size_t n = clip.skeleton.joints.size();
  bool same = source->clip.skeleton.joints.size() == n;
  for (std::size_t j = 0; same && j < n; ++j) same = source->clip.skeleton.joints[j].name == clip.skeleton.joints[j].name;
  if (!same) return make_error(clip_file + ": --truth source: the second read of the file has other joints");
  auto baked = std::make_shared<const Clip>(clip);
  return TruthFn([source, baked](double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation) {
    const std::size_t count = baked->skeleton.joints.size();
    rotation.resize(count);
    translation.resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      rotation[j] = source->own[j] ? source->motion(j, t) : sample_rotation(baked->rotations[j], t);
      const auto& track = baked->translations[j];
      translation[j] = track ? sample_translation(*track, t) : baked->skeleton.joints[j].offset;
    }
  });
}

}  // namespace rotinterp
