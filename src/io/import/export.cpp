// Collada through assimp's exporter: the clip as an aiScene.
#include "rotinterp/io/import/import.h"

#include "assimp_iosystem.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/files/one_line.h"
#include "rotinterp/clip/clip.h"
#include "rotinterp/io/files/key_times.h"
#include "rotinterp/track/sample.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/written_names.h"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace rotinterp {

namespace {

constexpr double kExportTicksPerSecond = 1.0;

aiMatrix4x4 node_matrix(const Vec3& t, const Quat& r) {
  const Mat3 m = r.toRotationMatrix();
  return aiMatrix4x4(static_cast<ai_real>(m(0, 0)), static_cast<ai_real>(m(0, 1)), static_cast<ai_real>(m(0, 2)),
                     static_cast<ai_real>(t.x()), static_cast<ai_real>(m(1, 0)), static_cast<ai_real>(m(1, 1)),
                     static_cast<ai_real>(m(1, 2)), static_cast<ai_real>(t.y()), static_cast<ai_real>(m(2, 0)),
                     static_cast<ai_real>(m(2, 1)), static_cast<ai_real>(m(2, 2)), static_cast<ai_real>(t.z()), 0, 0, 0, 1);
}

aiQuaternion to_ai(const Quat& q) {
  return aiQuaternion(static_cast<ai_real>(q.w()), static_cast<ai_real>(q.x()), static_cast<ai_real>(q.y()),
                      static_cast<ai_real>(q.z()));
}
aiVector3D to_ai(const Vec3& v) {
  return aiVector3D(static_cast<ai_real>(v.x()), static_cast<ai_real>(v.y()), static_cast<ai_real>(v.z()));
}

std::unique_ptr<aiScene> build_scene(const Clip& clip) {
  // Collada states its unit as the metre (assimp writes <unit meter="1">):
  // translations are converted with the clip's unit scale, as for glTF.
  const double metres = metres_per_unit(clip);
  auto scene = std::make_unique<aiScene>();
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  scene->mRootNode = new aiNode("RootNode");
  std::vector<aiNode*> nodes(n);
  std::vector<std::vector<aiNode*>> kids(n);
  std::vector<aiNode*> roots;
  const std::vector<std::string> names = written_joint_names(sk, NameForm::text);
  for (std::size_t j = 0; j < n; ++j) {
    nodes[j] = new aiNode(names[j]);
    nodes[j]->mTransformation = node_matrix(sk.joints[j].offset * metres, sk.joints[j].rest_rotation);
  }
  for (std::size_t j = 0; j < n; ++j) {
    const int p = sk.joints[j].parent;
    if (p < 0) roots.push_back(nodes[j]);
    else kids[static_cast<std::size_t>(p)].push_back(nodes[j]);
  }
  auto attach = [](aiNode* parent, const std::vector<aiNode*>& children) {
    if (children.empty()) return;
    parent->mNumChildren = static_cast<unsigned>(children.size());
    parent->mChildren = new aiNode*[children.size()];
    for (std::size_t i = 0; i < children.size(); ++i) {
      parent->mChildren[i] = children[i];
      children[i]->mParent = parent;
    }
  };
  attach(scene->mRootNode, roots);
  for (std::size_t j = 0; j < n; ++j) attach(nodes[j], kids[j]);

  // Ticks are seconds: assimp 5.2.5's FBX and Collada exporters write mTime as
  // seconds whatever mTicksPerSecond says (glTF divides by it, so 1 suits all three).
  const double tps = kExportTicksPerSecond;
  auto* anim = new aiAnimation();
  anim->mName = aiString(clip.name.empty() ? std::string("clip") : readable_text(clip.name));
  anim->mTicksPerSecond = tps;
  // Whole ticks: assimp's exporters truncate the take's end to an integer tick count.
  anim->mDuration = std::ceil(clip.end_time() * tps);
  anim->mNumChannels = static_cast<unsigned>(n);
  anim->mChannels = new aiNodeAnim*[n];
  for (std::size_t j = 0; j < n; ++j) {
    // Position, rotation and scaling keys at the same times: assimp's Collada
    // exporter skips channels whose key counts differ.
    const RotationTrack& r = clip.rotations[j];
    const std::optional<TranslationTrack>& tr = clip.translations[j];
    std::vector<double> times = r.times;
    if (tr) {
      times.insert(times.end(), tr->times.begin(), tr->times.end());
      std::sort(times.begin(), times.end());
      times.erase(std::unique(times.begin(), times.end()), times.end());
    }
    auto* ch = new aiNodeAnim();
    anim->mChannels[j] = ch;
    ch->mNodeName = aiString(names[j]);
    const auto count = static_cast<unsigned>(times.size());
    ch->mNumRotationKeys = ch->mNumPositionKeys = ch->mNumScalingKeys = count;
    ch->mRotationKeys = new aiQuatKey[count];
    ch->mPositionKeys = new aiVectorKey[count];
    ch->mScalingKeys = new aiVectorKey[count];
    for (unsigned k = 0; k < count; ++k) {
      const double tick = times[k] * tps;
      ch->mRotationKeys[k] = aiQuatKey(tick, to_ai(sample_rotation(r, times[k])));
      ch->mPositionKeys[k] = aiVectorKey(tick, to_ai((tr ? sample_translation(*tr, times[k]) : sk.joints[j].offset) * metres));
      ch->mScalingKeys[k] = aiVectorKey(tick, aiVector3D(1, 1, 1));
    }
  }
  scene->mNumAnimations = 1;
  scene->mAnimations = new aiAnimation*[1];
  scene->mAnimations[0] = anim;
  return scene;
}

}  // namespace

std::optional<std::string> assimp_export_format(const std::string& ext) {
  if (const FormatInfo* f = format_named(ext); f && f->id == FormatId::dae) return std::string("collada");
  return std::nullopt;
}

Status export_with_assimp(const Clip& clip, const std::filesystem::path& path, const std::string& format) {
  const std::string label = path.string();
  if (Status s = clip.validate(); !s) return s.failure(label + ": cannot write an invalid clip: ");
  const std::unique_ptr<aiScene> scene = build_scene(clip);
  AtomicOutput out(path);  // named: assimp's exporter opens a path
  if (Status s = out.status(); !s) return s;
  Assimp::Exporter exporter;
  auto* io = new CheckedIOSystem(label);  // owned by the exporter: every write checked
  exporter.SetIOHandler(io);
  aiReturn ret = aiReturn_FAILURE;
  try {
    ret = exporter.Export(scene.get(), format, out.temp_path().string(), 0);
  } catch (const std::exception& e) {
    return make_error(label + ": assimp could not export: " + one_line(e.what()));
  }
  if (const std::string e = io->error(); !e.empty()) return make_error(e);  // what made the export fail, if it did
  if (ret != aiReturn_SUCCESS) return make_error(label + ": assimp could not export: " + one_line(exporter.GetErrorString()));
  return out.commit();
}

}  // namespace rotinterp
