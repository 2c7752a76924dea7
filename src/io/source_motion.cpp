// read_file_source: a file's own motion in the one form resample, eval and render use
// (io/source_motion.h); each format's own reader behind it (FBX curves, glTF samplers,
// BVH frames).
#include "rotinterp/io/source_motion.h"
#include "rotinterp/io/files/formats.h"

#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/gltf/gltf_source.h"
#include "rotinterp/io/info.h"
#include "rotinterp/track/sample.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace rotinterp {

namespace {

// Every joint from the clip's keys: a BVH's frames are its keys.
FileSource frames_source(Clip clip) {
  FileSource out;
  out.clip = std::move(clip);
  out.own.assign(out.clip.skeleton.joints.size(), true);
  out.replays = "the file's frames";
  auto tracks = std::make_shared<const std::vector<RotationTrack>>(out.clip.rotations);
  out.motion = [tracks](std::size_t j, double t) { return sample_rotation((*tracks)[j], t); };
  return out;
}

// assimp reads a glTF key time t (float seconds) as the float nearest t·1000 ticks, so
// the clip's key lies within |t|·2⁻²⁴ of the sampler's (one float rounding). A clip time
// within four times that of a sampler key is taken as that key: a STEP sampler then
// holds the key the clip was read at, not the one before it.
constexpr double kFloatClockTolerance = 1.0 / (1 << 22);

double on_sampler_clock(const GltfSampler& sampler, double t) {
  const auto& times = sampler.times;
  const auto hi = std::lower_bound(times.begin(), times.end(), t);
  const double tolerance = std::abs(t) * kFloatClockTolerance + 1e-12;
  double nearest = t, best = tolerance;
  for (auto it : {hi, hi - (hi == times.begin() ? 0 : 1)})
    if (it != times.end() && std::abs(*it - t) <= best) best = std::abs(*it - t), nearest = *it;
  return nearest;
}

Result<FileSource> gltf_source(const std::filesystem::path& path, ClipFileInfo&& info, bool allow_external_files) {
  const std::string label = path.string();
  auto file = read_gltf_animations(path, allow_external_files);
  if (!file) return file.failure();
  // assimp keeps the file's animations in order: ours and the clip's share an index.
  if (info.selected >= file->animations.size() || file->animations[info.selected].name != info.animations[info.selected].name)
    return make_error(label + ": --method source: the file's animations read otherwise than assimp's");
  auto animation = std::make_shared<const GltfAnimation>(std::move(file->animations[info.selected]));
  const std::vector<int> node = gltf_node_of_joints(info.clip.skeleton, file->node_names);
  FileSource out;
  out.clip = std::move(info.clip);
  out.replays = "the file's animation samplers";
  std::vector<int> sampler;  // per joint: its rotation sampler, or -1
  for (int n : node) {
    sampler.push_back(n < 0 ? -1 : animation->nodes[static_cast<std::size_t>(n)].rotation);
    out.own.push_back(sampler.back() >= 0);
  }
  if (out.own_joints() == 0)
    return make_error(label + ": --method source: no joint has a rotation channel in animation '" + animation->name + "'");
  auto tracks = std::make_shared<const std::vector<RotationTrack>>(out.clip.rotations);
  // Clip time is glTF time (assimp keeps glTF's clock, io/gltf/gltf_source.h), up to the float
  // rounding of assimp's key times.
  out.motion = [animation, sampler, tracks](std::size_t j, double t) {
    if (sampler[j] < 0) return sample_rotation((*tracks)[j], t);
    const GltfSampler& s = animation->samplers[static_cast<std::size_t>(sampler[j])];
    return gltf_rotation_at(s, on_sampler_clock(s, t));
  };
  return out;
}

}  // namespace


std::size_t FileSource::own_joints() const { return static_cast<std::size_t>(std::count(own.begin(), own.end(), true)); }

Result<FileSource> read_file_source(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  ReadOptions with_curves = options;
  with_curves.read_curves = true;  // FBX only; other formats read as without
  Result<ClipFileInfo> info = inspect_clip(path, with_curves);
  if (!info) return info.failure();
  if (info->curves) {
    auto fbx = source_clip_of(std::move(*info), label);
    if (!fbx) return fbx.failure();
    return fbx_file_source(std::make_shared<const SourceClip>(std::move(*fbx)), label);
  }
  if (is_format(info->format, FormatId::glb) || is_format(info->format, FormatId::gltf))
    return gltf_source(path, std::move(*info), options.allow_external_files);
  if (is_format(info->format, FormatId::bvh)) return frames_source(std::move(info->clip));
  return make_error(label + ": --method source replays a file's own motion (FBX curves, glTF animation samplers, BVH "
                    "frames); this is a '" + info->format + "' file (use an interpolator, e.g. clamped)");
}

Result<Clip> read_clip_with_source_motion(const std::filesystem::path& path, const ReadOptions& options,
                                          SourceMotion& motion) {
  auto source = read_file_source(path, options);
  if (!source) return source.failure();
  motion = std::move(source->motion);
  return std::move(source->clip);
}

std::size_t replay_source_rotations(Clip& clip, const FileSource& source, const std::vector<std::string>& keep) {
  std::size_t replayed = 0;
  for (std::size_t j = 0; j < clip.rotations.size() && j < source.own.size(); ++j) {
    if (!source.own[j] || std::find(keep.begin(), keep.end(), clip.skeleton.joints[j].name) != keep.end()) continue;
    RotationTrack& track = clip.rotations[j];
    for (std::size_t k = 0; k < track.times.size(); ++k) track.keys[k] = source.motion(j, track.times[k]);
    track.make_sign_continuous();
    ++replayed;
  }
  return replayed;
}

}  // namespace rotinterp
