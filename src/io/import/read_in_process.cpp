// The whole read in this process, assimp included: what the importer process runs
// (import.h). Every format but BVH and FBX 6.1 goes through assimp and
// scene_to_clip(); BVH through our own pass, with ReadOptions::cross_check_with_assimp
// compared with assimp's reading; FBX 6.1 (which assimp refuses) through our own
// FBX reader (fbx_legacy.h).
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/files/one_line.h"
#include "fbx_legacy.h"
#include "rotinterp/io/import/import.h"
#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/gltf/gltf_source.h"
#include "scene_body.h"
#include "scene_parts.h"
#include "scene_to_clip.h"
#include "rotinterp/io/files/file_errors.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

// The importer as the reads configure it.
void configure(Assimp::Importer& importer, const ReadOptions& options) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, options.fold_fbx_helpers);
}

// importer.ReadFile, with its failures (an error string, out of memory, an
// exception) as one line in `error`; nullptr then.
const aiScene* import_scene(Assimp::Importer& importer, const fs::path& path, std::string& error) {
  try {
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    if (!scene) error = one_line(importer.GetErrorString());
    return scene;
  } catch (const std::bad_alloc&) {
    error = "out of memory while importing";
  } catch (const std::exception& e) {
    error = one_line(e.what());
  }
  return nullptr;
}

Result<std::size_t> select_animation(const aiScene* scene, const std::string& want, const std::string& label) {
  const std::size_t n = scene->mNumAnimations;
  if (want.empty()) return std::size_t{0};
  for (std::size_t a = 0; a < n; ++a)
    if (want == scene->mAnimations[a]->mName.C_Str()) return a;
  if (std::all_of(want.begin(), want.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const std::size_t index = want.size() > 9 ? n : static_cast<std::size_t>(std::stoul(want));
    if (index < n) return index;
    return make_error(label + ": there is no animation " + want + " (the file has " + std::to_string(n) + ", numbered from 0)");
  }
  std::string names;
  for (std::size_t a = 0; a < n; ++a) names += (a ? ", '" : "'") + std::string(scene->mAnimations[a]->mName.C_Str()) + "'";
  return make_error(label + ": no animation named '" + want + "' (the file has " + names + ")");
}

// "1 mesh, 2 nodes: RootNode, Cube": what a file without animation holds (info
// shows it; every other command just says there is no animation).
std::string scene_contents(const aiScene* scene) {
  std::vector<std::string> names;
  std::vector<const aiNode*> todo = {scene->mRootNode};
  while (!todo.empty()) {
    const aiNode* n = todo.back();
    todo.pop_back();
    if (!n) continue;
    names.push_back(n->mName.C_Str());
    for (unsigned c = n->mNumChildren; c-- > 0;) todo.push_back(n->mChildren[c]);
  }
  std::string s = std::to_string(scene->mNumMeshes) + (scene->mNumMeshes == 1 ? " mesh, " : " meshes, ") +
                  std::to_string(names.size()) + (names.size() == 1 ? " node" : " nodes");
  constexpr std::size_t kNamesShown = 6;
  for (std::size_t i = 0; i < names.size() && i < kNamesShown; ++i) s += (i ? ", " : ": ") + names[i];
  if (names.size() > kNamesShown) s += ", …";
  return s;
}

// Each FBX take's start in file time (fbx_take_span), by name, from our own reader.
void add_take_starts(const FbxAnimation& curves, std::vector<AnimationSummary>& animations) {
  for (AnimationSummary& s : animations)
    for (const FbxTake& take : curves.takes)
      if (take.name == s.name)
        s.start = static_cast<double>(fbx_take_span(take).start) / static_cast<double>(kFbxTicksPerSecond);
}

// Every format but BVH: the import, the animations, and the clip built from the
// scene. `info` comes with its format set.
Status read_with_assimp(const fs::path& path, const ReadOptions& options, ClipFileInfo& info,
                        const Warnings& warn) {
  const std::string label = path.string();
  Assimp::Importer importer;
  configure(importer, options);
  std::string assimp_error;
  const aiScene* scene = import_scene(importer, path, assimp_error);
  if (!scene) {
    if (assimp_error.find("No suitable reader") != std::string::npos || assimp_error.empty())
      return make_error(label + ": not a motion file (formats read: " + read_formats_text() + ")", file_error::unreadable);
    return make_error(label + ": cannot read: " + assimp_error, file_error::unreadable);
  }
  if (scene->mNumAnimations == 0) {
    info.holds = scene_contents(scene);
    return make_error(label + ": the file has no animation (it holds " + info.holds + ")", file_error::no_animation);
  }
  // FBX: assimp re-bases each take to its span's start (LocalStart, else its first
  // key), where its file time is out of sight (read_here adds it from our own reader).
  const bool fbx = is_format(info.format, FormatId::fbx);
  for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
    const aiAnimation* an = scene->mAnimations[a];
    AnimationSummary s;
    s.name = an->mName.C_Str();
    s.default_rate = !(an->mTicksPerSecond > 0.0);
    s.ticks_per_second = s.default_rate ? kDefaultTicksPerSecond : an->mTicksPerSecond;
    s.duration = an->mDuration / s.ticks_per_second;
    s.channels = an->mNumChannels;
    Result<scene_parts::KeyTimes> keys = scene_parts::key_times(
        an, fbx ? std::optional(scene_parts::TickSpan{0.0, an->mDuration}) : std::nullopt, label);
    if (!keys) return make_error(keys.error(), file_error::unreadable);
    s.keys = keys->distinct;
    s.start = fbx ? NAN : keys->first / s.ticks_per_second;
    if (!fbx) s.duration = keys->all.empty() ? 0.0 : (keys->last - keys->first) / s.ticks_per_second;
    s.rate_stated = scene_states_rate(scene) && !s.default_rate;
    const double frame_time = s.rate_stated ? 1.0 / s.ticks_per_second
                                            : scene_parts::detect_frame_time(*keys, s.ticks_per_second);
    s.frame_rate_hz = frame_time > 0.0 ? 1.0 / frame_time : 0.0;
    info.animations.push_back(s);
  }
  Result<std::size_t> sel = select_animation(scene, options.animation, label);
  if (!sel) return sel.failure();
  info.selected = *sel;
  const aiAnimation* anim = scene->mAnimations[info.selected];
  const AnimationSummary& summary = info.animations[info.selected];
  if (!std::isfinite(anim->mTicksPerSecond) || anim->mTicksPerSecond < 0.0)
    return make_error(label + ": animation '" + summary.name + "' has an invalid tick rate", file_error::unreadable);
  if (summary.default_rate)
    warn(label + ": animation '" + summary.name + "' gives 0 ticks per second; assuming " +
         std::to_string(static_cast<int>(kDefaultTicksPerSecond)));
  info.clip.name = summary.name.empty() ? path.stem().string() : summary.name;
  Status filled = scene_to_clip(scene, anim, summary.ticks_per_second, fbx ? std::optional(anim->mDuration) : std::nullopt,
                                info.clip, info.folded_helpers, warn, label);
  if (!filled) return make_error(filled.error(), file_error::unreadable);
  if (options.read_body) info.body = scene_body(scene, info.clip, path);
  return Ok{};
}

// assimp parses BVH values and builds rotations in 32-bit float: its keys differ from
// the exact ones by up to ~5e-5° on the real clips (370° angles). More than this
// means the two parsers disagree about the file.
constexpr double kAssimpAgreementRadians = 1e-3 * kPi / 180.0;

// assimp's reading of a BVH against ours: same joints and one key per frame (else
// an error), same rotations within float precision (else a warning).
Status compare_with_assimp(const BvhFile& bvh, const Clip& clip, const aiAnimation* anim, const Warnings& warn,
                           const std::string& label) {
  std::map<std::string, const aiNodeAnim*> channels;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) channels[anim->mChannels[c]->mNodeName.C_Str()] = anim->mChannels[c];
  for (std::size_t j = 0; j < bvh.joints.size(); ++j) {
    const std::string& name = bvh.joints[j].name;
    const auto it = channels.find(name);
    if (it == channels.end())
      return make_error(label + ": assimp and rotinterp disagree about the HIERARCHY: no animation channel for joint '" +
                        name + "'");
    const aiNodeAnim* ch = it->second;
    if (ch->mNumRotationKeys != bvh.frames)
      return make_error(label + ": assimp read " + std::to_string(ch->mNumRotationKeys) + " frames for joint '" + name +
                        "', rotinterp " + std::to_string(bvh.frames));
    double worst = 0.0;
    std::size_t worst_frame = 0;
    for (std::size_t f = 0; f < bvh.frames; ++f) {
      const aiQuaternion& q = ch->mRotationKeys[f].mValue;
      const double d = angular_distance(clip.rotations[j].keys[f], normalized_or_identity(Quat(q.w, q.x, q.y, q.z)));
      if (d > worst) worst = d, worst_frame = f;
    }
    if (worst > kAssimpAgreementRadians)
      warn(label + ": assimp reads joint '" + name + "' differently (" + std::to_string(worst * 180.0 / kPi) +
           " degrees at frame " + std::to_string(worst_frame) + "); rotinterp's reading is used");
  }
  return Ok{};
}

// BVH by our own pass; with ReadOptions::cross_check_with_assimp also assimp's
// reading (which names the animation), compared.
Status read_bvh_checked(const fs::path& path, const ReadOptions& options, ClipFileInfo& info, const Warnings& warn) {
  const std::string label = path.string();
  Result<BvhFile> bvh = read_bvh_file(path, info, warn);
  if (!bvh) return bvh.failure();
  Assimp::Importer importer;
  configure(importer, options);
  std::string assimp_error;
  const aiScene* scene = options.cross_check_with_assimp ? import_scene(importer, path, assimp_error) : nullptr;
  const aiAnimation* anim = nullptr;
  if (!options.cross_check_with_assimp) {
    // No assimp: nothing to compare.
  } else if (scene && scene->mNumAnimations > 0) {
    anim = scene->mAnimations[0];
  } else {
    warn(label + ": assimp could not read the motion (" + (assimp_error.empty() ? "no animation" : assimp_error) +
         "); read with rotinterp's own BVH pass");
  }
  if (Status st = bvh_file_to_clip(*bvh, anim ? anim->mName.C_Str() : "", path, options, info); !st) return st;
  if (!anim) return Ok{};
  if (Status st = compare_with_assimp(*bvh, info.clip, anim, warn, label); !st)
    return make_error(st.error(), file_error::unreadable);
  return Ok{};
}

// FBX 7 and glTF are read by our own readers before assimp sees them: they check
// every declared size before allocating (io/files/limits.h), where assimp allocates
// what a lying count asks, and they refuse keys assimp takes in silence (reversed or
// NaN times, NaN values): both paths then accept the same files (docs/limits.md).
// Keys they repaired are warnings; the FBX curves are kept for ReadOptions::read_curves.
Result<std::optional<FbxAnimation>> read_ahead_of_assimp(const fs::path& path, const std::string& ext,
                                                         const ReadOptions& options, const Warnings& warn) {
  const std::string label = path.string();
  if (is_format(ext, FormatId::fbx)) {
    Result<FbxAnimation> curves = read_fbx_curves_file(path, label);
    if (!curves) return curves.failure();
    // Our curves drop an exactly repeated key, but assimp, which makes the clip here,
    // drops the whole curve: the joint would stay at rest under a warning that says
    // "repaired". Refused instead (docs/limits.md).
    if (!curves->repairs.empty())
      return make_error(curves->repairs.front() +
                            " by our reader, but assimp, which reads FBX 7 files, drops such a curve and would leave "
                            "its joint at rest: refused",
                        file_error::unreadable);
    return std::optional<FbxAnimation>(std::move(*curves));
  }
  if (is_format(ext, FormatId::glb) || is_format(ext, FormatId::gltf)) {
    Result<GltfAnimations> gltf = read_gltf_animations(path, options.allow_external_files);
    if (!gltf) return gltf.failure();
    for (const std::string& w : gltf->repairs) warn(label + ": " + w);
  }
  return std::optional<FbxAnimation>();
}

Status read_here(const fs::path& path, const ReadOptions& options, ClipFileInfo& info, const Warnings& warn) {
  const std::string label = path.string();
  if (Status s = check_file(path, label); !s) return s.failure();
  const std::string ext = extension_of(path);
  info.format = ext;
  const bool fbx = is_format(ext, FormatId::fbx);
  const bool bvh = is_bvh(path, ext), legacy = !bvh && fbx && is_legacy_fbx(path);
  std::optional<FbxAnimation> curves;
  if (!bvh && !legacy) {
    Result<std::optional<FbxAnimation>> ahead = read_ahead_of_assimp(path, ext, options, warn);
    if (!ahead) return ahead.failure();
    curves = std::move(*ahead);
  }
  Status st = bvh      ? read_bvh_checked(path, options, info, warn)
              : legacy ? read_legacy_fbx(path, options, info, warn)
                       : read_with_assimp(path, options, info, warn);
  if (!st) return st;
  if (legacy && info.curves)
    for (const std::string& w : info.curves->repairs) warn(w);
  if (options.read_curves && fbx && !info.curves && curves) info.curves = std::move(*curves);
  if (info.curves) add_take_starts(*info.curves, info.animations);
  return check_clip(info, label, options);
}

}  // namespace

namespace detail {

ReadOutcome read_in_this_process(const fs::path& path, const ReadOptions& options) {
  ReadOutcome out;
  const Warnings keep{nullptr, &out.info.warnings};
  try {
    if (Status st = read_here(path, options, out.info, keep); !st) {
      out.error = st.error();
      out.kind = st.error_kind();
    }
  } catch (const std::bad_alloc&) {
    out.error = path.string() + ": out of memory while reading";
    out.kind = file_error::out_of_memory;
  } catch (const std::exception& e) {
    out.error = path.string() + ": " + one_line(e.what());
  }
  if (out.error) {
    ClipFileInfo found_before;  // what a failed reading still tells
    found_before.warnings = std::move(out.info.warnings);
    found_before.holds = std::move(out.info.holds);
    out.info = std::move(found_before);
  }
  return out;
}

}  // namespace detail

}  // namespace rotinterp
