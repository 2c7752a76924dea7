// A character's body from an assimp scene (scene_body.h): every mesh node's meshes
// as one BodyMesh, their bones, materials and base-colour images.
#include "scene_body.h"

#include "scene_parts.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

RowMajor4 row_major(const Eigen::Matrix4d& m) {
  RowMajor4 out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[static_cast<std::size_t>(4 * r + c)] = m(r, c);
  return out;
}

Eigen::Matrix4d world_of(const aiNode* node) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (; node; node = node->mParent) m = scene_parts::to_eigen(node->mTransformation) * m;
  return m;
}

// "image/png" or "image/jpeg" from the bytes' signature; "" for anything else, which
// glTF cannot hold (TGA, DDS, …).
std::string image_mime(const std::string& bytes) {
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0) return "image/png";
  if (bytes.size() >= 3 && std::memcmp(bytes.data(), "\xff\xd8\xff", 3) == 0) return "image/jpeg";
  return "";
}

std::string file_name_of(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

class BodyBuilder {
 public:
  BodyBuilder(const aiScene* scene, const Clip& clip, const fs::path& source) : scene_(scene), source_(source) {
    for (const Joint& j : clip.skeleton.joints) joints_.insert(j.name);
  }

  CharacterBody build() {
    for (unsigned m = 0; m < scene_->mNumMaterials; ++m) body_.materials.push_back(material(scene_->mMaterials[m]));
    visit(scene_->mRootNode, "");
    return std::move(body_);
  }

 private:
  bool is_joint(const aiNode* node) const { return joints_.count(node->mName.C_Str()) > 0; }

  void visit(const aiNode* node, const std::string& joint_above) {
    if (node->mNumMeshes > 0) body_.meshes.push_back(mesh(node, joint_above));
    const std::string here = is_joint(node) ? node->mName.C_Str() : joint_above;
    for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c], here);
  }

  BodyMesh mesh(const aiNode* node, const std::string& joint_above) {
    BodyMesh out;
    out.name = node->mName.C_Str();
    out.world = row_major(world_of(node));
    out.parent_joint = joint_above;
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      if (node->mMeshes[i] < scene_->mNumMeshes) {
        const aiMesh* m = scene_->mMeshes[node->mMeshes[i]];
        if (m->mPrimitiveTypes & (aiPrimitiveType_TRIANGLE | aiPrimitiveType_POLYGON)) out.parts.push_back(part(m));
        else note("mesh '" + std::string(m->mName.C_Str()) + "' has no triangles (points or lines only); not kept");
      }
    return out;
  }

  BodyPart part(const aiMesh* m) {
    BodyPart p;
    const unsigned n = m->mNumVertices;
    for (unsigned v = 0; v < n; ++v) {
      const aiVector3D& x = m->mVertices[v];
      p.positions.insert(p.positions.end(), {x.x, x.y, x.z});
      if (m->mNormals) p.normals.insert(p.normals.end(), {m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z});
      if (m->mTextureCoords[0] && m->mNumUVComponents[0] >= 2)
        p.uvs.insert(p.uvs.end(), {m->mTextureCoords[0][v].x, m->mTextureCoords[0][v].y});
      if (m->mColors[0]) p.colours.insert(p.colours.end(), {m->mColors[0][v].r, m->mColors[0][v].g, m->mColors[0][v].b, m->mColors[0][v].a});
    }
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      const aiFace& face = m->mFaces[f];
      for (unsigned k = 1; k + 1 < face.mNumIndices; ++k)  // a fan: assimp's FBX faces are polygons; points and lines none
        p.triangles.insert(p.triangles.end(), {face.mIndices[0], face.mIndices[k], face.mIndices[k + 1]});
    }
    p.material = m->mMaterialIndex < scene_->mNumMaterials ? static_cast<int>(m->mMaterialIndex) : -1;
    for (unsigned b = 0; b < m->mNumBones; ++b) {
      const aiBone* bone = m->mBones[b];
      const aiNode* node = scene_->mRootNode->FindNode(bone->mName);
      if (!node || !is_joint(node)) {
        note("bone '" + std::string(bone->mName.C_Str()) + "' of mesh '" + m->mName.C_Str() +
             "' is no joint of the skeleton; its weights are dropped");
        continue;
      }
      BodyBone out;
      out.joint = node->mName.C_Str();
      out.mesh_to_world = row_major(world_of(node) * scene_parts::to_eigen(bone->mOffsetMatrix));
      for (unsigned w = 0; w < bone->mNumWeights; ++w)
        if (bone->mWeights[w].mVertexId < n) {
          out.vertices.push_back(bone->mWeights[w].mVertexId);
          out.weights.push_back(bone->mWeights[w].mWeight);
        }
      p.bones.push_back(std::move(out));
    }
    return p;
  }

  BodyMaterial material(const aiMaterial* m) {
    BodyMaterial out;
    aiString name;
    if (m->Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS) out.name = name.C_Str();
    aiColor4D c;
    if (m->Get(AI_MATKEY_BASE_COLOR, c) == aiReturn_SUCCESS || m->Get(AI_MATKEY_COLOR_DIFFUSE, c) == aiReturn_SUCCESS)
      out.base_colour = {c.r, c.g, c.b, 1.0};
    float opacity = 1.0f;
    if (m->Get(AI_MATKEY_OPACITY, opacity) == aiReturn_SUCCESS && opacity >= 0.0f && opacity <= 1.0f)
      out.base_colour[3] = opacity;
    aiString path;
    if (m->GetTexture(aiTextureType_BASE_COLOR, 0, &path) == aiReturn_SUCCESS ||
        m->GetTexture(aiTextureType_DIFFUSE, 0, &path) == aiReturn_SUCCESS)
      out.image = image(path.C_Str(), out.name);
    return out;
  }

  // The image at `path` (embedded, or a file in the source's folder), its index;
  // −1 with a note where it cannot be kept.
  int image(const std::string& path, const std::string& material) {
    if (const auto it = images_.find(path); it != images_.end()) return it->second;
    BodyImage img;
    img.name = file_name_of(path);
    if (const aiTexture* t = scene_->GetEmbeddedTexture(path.c_str())) {
      if (t->mHeight != 0) return none(path, material, "is stored as raw texels, which glTF cannot hold");
      img.bytes.assign(reinterpret_cast<const char*>(t->pcData), t->mWidth);
    } else {
      // Only the source's own folder is looked in (a texture path is often another
      // machine's, "C:\Dev\…"): the file of that name beside the source.
      const fs::path beside = source_.parent_path() / img.name;
      std::ifstream in(beside, std::ios::binary);
      if (img.name.empty() || !in) return none(path, material, "is not beside the file");
      std::ostringstream bytes;
      bytes << in.rdbuf();
      img.bytes = bytes.str();
    }
    img.mime_type = image_mime(img.bytes);
    if (img.mime_type.empty()) return none(path, material, "is neither PNG nor JPEG, which glTF cannot hold");
    body_.images.push_back(std::move(img));
    return images_[path] = static_cast<int>(body_.images.size() - 1);
  }

  int none(const std::string& path, const std::string& material, const std::string& why) {
    note("texture '" + file_name_of(path) + "' of material '" + material + "' " + why + "; its colour is kept");
    return images_[path] = -1;
  }

  void note(const std::string& line) { body_.notes.push_back(line); }

  const aiScene* scene_;
  fs::path source_;
  std::set<std::string> joints_;
  std::map<std::string, int> images_;
  CharacterBody body_;
};

}  // namespace

CharacterBody scene_body(const aiScene* scene, const Clip& clip, const std::filesystem::path& source) {
  return BodyBuilder(scene, clip, source).build();
}

}  // namespace rotinterp
