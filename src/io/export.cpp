#include "export.h"

#include "rotinterp/io/atomic_file.h"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

namespace rotinterp {

namespace {

// Ticks per second of an exported clip without a frame time: milliseconds.
constexpr double kExportTicksPerSecondWithoutFrameTime = 1000.0;

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
  auto scene = std::make_unique<aiScene>();
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  scene->mRootNode = new aiNode("RootNode");
  std::vector<aiNode*> nodes(n);
  std::vector<std::vector<aiNode*>> kids(n);
  std::vector<aiNode*> roots;
  for (std::size_t j = 0; j < n; ++j) {
    nodes[j] = new aiNode(sk.joints[j].name);
    nodes[j]->mTransformation = node_matrix(sk.joints[j].offset, sk.joints[j].rest_rotation);
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

  const double tps = clip.frame_time > 0.0 ? 1.0 / clip.frame_time : kExportTicksPerSecondWithoutFrameTime;
  auto* anim = new aiAnimation();
  anim->mName = aiString(clip.name.empty() ? std::string("clip") : clip.name);
  anim->mTicksPerSecond = tps;
  anim->mDuration = (clip.end_time() - clip.start_time()) * tps;
  anim->mNumChannels = static_cast<unsigned>(n);
  anim->mChannels = new aiNodeAnim*[n];
  for (std::size_t j = 0; j < n; ++j) {
    auto* ch = new aiNodeAnim();
    anim->mChannels[j] = ch;
    ch->mNodeName = aiString(sk.joints[j].name);
    const RotationTrack& r = clip.rotations[j];
    ch->mNumRotationKeys = static_cast<unsigned>(r.keys.size());
    ch->mRotationKeys = new aiQuatKey[r.keys.size()];
    for (std::size_t k = 0; k < r.keys.size(); ++k)
      ch->mRotationKeys[k] = aiQuatKey(r.times[k] * tps, to_ai(r.keys[k]));
    if (const auto& t = clip.translations[j]) {
      ch->mNumPositionKeys = static_cast<unsigned>(t->keys.size());
      ch->mPositionKeys = new aiVectorKey[t->keys.size()];
      for (std::size_t k = 0; k < t->keys.size(); ++k)
        ch->mPositionKeys[k] = aiVectorKey(t->times[k] * tps, to_ai(t->keys[k]));
    } else {
      ch->mNumPositionKeys = 1;
      ch->mPositionKeys = new aiVectorKey[1];
      ch->mPositionKeys[0] = aiVectorKey(r.times.front() * tps, to_ai(sk.joints[j].offset));
    }
    ch->mNumScalingKeys = 1;
    ch->mScalingKeys = new aiVectorKey[1];
    ch->mScalingKeys[0] = aiVectorKey(r.times.front() * tps, aiVector3D(1, 1, 1));
  }
  scene->mNumAnimations = 1;
  scene->mAnimations = new aiAnimation*[1];
  scene->mAnimations[0] = anim;
  return scene;
}

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

std::optional<std::string> assimp_export_format(const std::string& ext) {
  if (ext == ".fbx") return std::string("fbx");
  if (ext == ".gltf") return std::string("gltf2");
  if (ext == ".glb") return std::string("glb2");
  if (ext == ".dae") return std::string("collada");
  return std::nullopt;
}

Status export_with_assimp(const Clip& clip, const std::filesystem::path& path, const std::string& format) {
  const std::string label = path.string();
  if (Status s = clip.validate(); !s) return make_error(label + ": cannot write an invalid clip: " + s.error());
  const std::unique_ptr<aiScene> scene = build_scene(clip);
  AtomicOutput out(path);
  Assimp::Exporter exporter;
  aiReturn ret = aiReturn_FAILURE;
  try {
    ret = exporter.Export(scene.get(), format, out.temp_path().string(), 0);
  } catch (const std::exception& e) {
    return make_error(label + ": assimp could not export: " + one_line(e.what()));
  }
  if (ret != aiReturn_SUCCESS) return make_error(label + ": assimp could not export: " + one_line(exporter.GetErrorString()));
  return out.commit();
}

}  // namespace rotinterp
