// A character's body in a glTF document (gltf_body.h).
#include "gltf_body.h"

#include "rotinterp/io/files/kept_text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace rotinterp::gltf {

namespace {

using json = nlohmann::json;
constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr std::size_t kWeightsPerVertex = 4;

Eigen::Matrix4d matrix(const RowMajor4& m) {
  Eigen::Matrix4d e;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) e(r, c) = m[static_cast<std::size_t>(4 * r + c)];
  return e;
}

// The metre form of a transform in source units: D·M·D⁻¹ scales its translation.
Eigen::Matrix4d in_metres(Eigen::Matrix4d m, double metres) {
  m.topRightCorner<3, 1>() *= metres;
  return m;
}

void put_matrix(std::string& bin, const Eigen::Matrix4d& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) put_float(bin, m(r, c));  // column-major
}

bool all_finite(const std::vector<float>& v) {
  return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
}

// A vertex's weights: (skin slot, weight), the heaviest first.
using Weights = std::vector<std::pair<std::uint16_t, double>>;

class BodyWriter {
 public:
  BodyWriter(Builder& b, json& doc, const Skeleton& sk, double metres) : b_(b), doc_(doc), metres_(metres) {
    const WorldPose rest = rest_pose(sk);
    for (std::size_t j = 0; j < sk.joints.size(); ++j) {
      joint_of_[sk.joints[j].name] = j;
      names_.push_back(sk.joints[j].name);
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m.topLeftCorner<3, 3>() = rest.rotation[j].toRotationMatrix();
      m.topRightCorner<3, 1>() = rest.position[j] * metres;
      joint_world_.push_back(m);
    }
  }

  Result<BodyKept> add(const CharacterBody& body) {
    for (const BodyMaterial& m : body.materials) add_material(m, body);
    for (const BodyMesh& mesh : body.meshes)
      if (!mesh.parts.empty())
        if (Status s = add_mesh(mesh, body); !s) return s.failure();
    if (!materials_.empty()) doc_["materials"] = materials_;
    if (!images_.empty()) {
      doc_["images"] = images_;
      doc_["textures"] = textures_;
      doc_["samplers"] = json::array({json::object()});
    }
    if (!meshes_.empty()) doc_["meshes"] = meshes_;
    kept_.notes.insert(kept_.notes.begin(), body.notes.begin(), body.notes.end());
    return std::move(kept_);
  }

 private:
  void add_material(const BodyMaterial& m, const CharacterBody& body) {
    json pbr = {{"baseColorFactor", {m.base_colour[0], m.base_colour[1], m.base_colour[2], m.base_colour[3]}},
                {"metallicFactor", 0.0},
                {"roughnessFactor", 1.0}};
    if (m.image >= 0 && static_cast<std::size_t>(m.image) < body.images.size()) {
      const BodyImage& image = body.images[static_cast<std::size_t>(m.image)];
      const auto [it, fresh] = image_index_.emplace(m.image, images_.size());
      if (fresh) {
        const std::size_t start = b_.bin.size();
        b_.bin += image.bytes;
        b_.views.push_back({{"buffer", 0}, {"byteOffset", start}, {"byteLength", image.bytes.size()}});
        b_.bin.append((4 - b_.bin.size() % 4) % 4, '\0');
        images_.push_back({{"name", image.name}, {"mimeType", image.mime_type}, {"bufferView", b_.views.size() - 1}});
        textures_.push_back({{"source", images_.size() - 1}, {"sampler", 0}});
        ++kept_.images;
      }
      pbr["baseColorTexture"] = {{"index", it->second}};
    }
    json out = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
    if (m.base_colour[3] < 1.0) out["alphaMode"] = "BLEND";
    materials_.push_back(out);
    ++kept_.materials;
  }

  // A float accessor of `values` (`width` per element): its index.
  int floats(const std::vector<float>& values, std::size_t width, const char* type, bool bounds = false) {
    const std::size_t start = b_.bin.size();
    for (float v : values) put_float(b_.bin, v);
    json extra = json::object();
    if (bounds) {
      json lo = json::array(), hi = json::array();
      for (std::size_t c = 0; c < width; ++c) {
        float l = INFINITY, h = -INFINITY;
        for (std::size_t i = c; i < values.size(); i += width) l = std::min(l, values[i]), h = std::max(h, values[i]);
        lo.push_back(l), hi.push_back(h);
      }
      extra = {{"min", lo}, {"max", hi}};
    }
    return b_.accessor(start, values.size() / width, type, extra);
  }

  template <class T>
  int integers(const std::vector<T>& values, std::size_t width, const char* type, int component) {
    const std::size_t start = b_.bin.size();
    for (T v : values) b_.bin.append(reinterpret_cast<const char*>(&v), sizeof v);  // little-endian machines only
    b_.bin.append((4 - b_.bin.size() % 4) % 4, '\0');
    const int a = b_.accessor(start, values.size() / width, type, {{"componentType", component}});
    b_.views.back()["byteLength"] = values.size() * sizeof(T);
    return a;
  }

  Status add_mesh(const BodyMesh& mesh, const CharacterBody& body) {
    const std::string what = "mesh '" + mesh.name + "'";
    // Vertices are written where the mesh node puts them (world, metres: true size in
    // any reader, skinned or not), so the inverse bind matrices carry no node transform.
    const Eigen::Matrix4d world = in_metres(matrix(mesh.world), metres_);
    const Eigen::Matrix4d world_inverse = world.inverse();
    const Eigen::Matrix3d normal_matrix = world.topLeftCorner<3, 3>().inverse().transpose();
    const bool mirrored = world.topLeftCorner<3, 3>().determinant() < 0.0;  // the winding turns over
    if (!world_inverse.allFinite()) return make_error(what + " has a node transform that cannot be inverted");
    // The skin: every joint a part binds, in order, with its inverse bind matrix.
    std::vector<std::size_t> joints;
    std::vector<Eigen::Matrix4d> ibms;
    std::map<std::size_t, std::uint16_t> slot_of;
    auto slot = [&](const std::string& name, const RowMajor4& mesh_to_world) -> std::optional<std::uint16_t> {
      const auto j = joint_of_.find(name);
      if (j == joint_of_.end()) return std::nullopt;
      if (const auto s = slot_of.find(j->second); s != slot_of.end()) return s->second;
      if (joints.size() >= 0xFFFF) return std::nullopt;
      joints.push_back(j->second);
      ibms.push_back(joint_world_[j->second].inverse() * in_metres(matrix(mesh_to_world), metres_) * world_inverse);
      return slot_of[j->second] = static_cast<std::uint16_t>(joints.size() - 1);
    };
    const bool skinned = !mesh.parent_joint.empty() ||
                         std::any_of(mesh.parts.begin(), mesh.parts.end(), [](const BodyPart& p) { return !p.bones.empty(); });
    json primitives = json::array();
    std::size_t over_four = 0, unnormalized = 0, unweighted = 0;
    for (const BodyPart& part : mesh.parts) {
      const std::size_t n = part.positions.size() / 3;
      if (part.positions.size() != 3 * n || n == 0 || !all_finite(part.positions) || !all_finite(part.normals) ||
          !all_finite(part.uvs) || !all_finite(part.colours) || (!part.normals.empty() && part.normals.size() != 3 * n) ||
          (!part.uvs.empty() && part.uvs.size() != 2 * n) || (!part.colours.empty() && part.colours.size() != 4 * n) ||
          part.triangles.size() % 3 != 0 ||
          std::any_of(part.triangles.begin(), part.triangles.end(), [&](std::uint32_t i) { return i >= n; }))
        return make_error(what + " is not a mesh (counts, indices or numbers out of range)");
      std::vector<float> positions(3 * n);
      for (std::size_t v = 0; v < n; ++v) {
        const Vec3 local = Eigen::Map<const Eigen::Vector3f>(&part.positions[3 * v]).cast<double>() * metres_;
        Eigen::Map<Eigen::Vector3f> out(&positions[3 * v]);
        out = (world * local.homogeneous()).head<3>().cast<float>();
      }
      json attributes = {{"POSITION", floats(positions, 3, "VEC3", true)}};
      if (!part.normals.empty()) {
        std::vector<float> normals(3 * n);
        for (std::size_t v = 0; v < n; ++v) {
          const Vec3 x = normal_matrix * Eigen::Map<const Eigen::Vector3f>(&part.normals[3 * v]).cast<double>();
          const double len = x.norm();  // the spec asks unit normals
          Eigen::Map<Eigen::Vector3f> out(&normals[3 * v]);
          out = (len > 0.0 && std::isfinite(len) ? Vec3(x / len) : Vec3::UnitZ()).cast<float>();
        }
        attributes["NORMAL"] = floats(normals, 3, "VEC3");
      }
      if (!part.uvs.empty()) {
        std::vector<float> uvs = part.uvs;
        for (std::size_t v = 0; v < n; ++v) uvs[2 * v + 1] = 1.0f - uvs[2 * v + 1];  // glTF's v runs down
        attributes["TEXCOORD_0"] = floats(uvs, 2, "VEC2");
      }
      if (!part.colours.empty()) attributes["COLOR_0"] = floats(part.colours, 4, "VEC4");
      if (skinned) {
        std::vector<Weights> weights(n);
        for (const BodyBone& bone : part.bones) {
          if (bone.vertices.size() != bone.weights.size()) continue;
          std::optional<std::uint16_t> s;  // a bone that weighs no vertex is no joint of the skin (nor a vertex group)
          for (std::size_t i = 0; i < bone.vertices.size(); ++i)
            if (bone.vertices[i] < n && std::isfinite(bone.weights[i]) && bone.weights[i] > 0.0f) {
              if (!s && !(s = slot(bone.joint, bone.mesh_to_world))) break;
              weights[bone.vertices[i]].emplace_back(*s, bone.weights[i]);
            }
        }
        // A rigid part, and a vertex no bone weighs: moved by the joint above the
        // mesh (else the skin's first), as the mesh node would move it.
        const std::string anchor = !mesh.parent_joint.empty() ? mesh.parent_joint
                                   : joints.empty()           ? std::string()
                                                              : names_[joints.front()];
        std::vector<std::uint16_t> joint4(kWeightsPerVertex * n, 0);
        std::vector<float> weight4(kWeightsPerVertex * n, 0.0f);
        for (std::size_t v = 0; v < n; ++v) {
          Weights& w = weights[v];
          if (w.empty()) {
            const auto s = anchor.empty() ? std::nullopt : slot(anchor, mesh.world);
            if (!s) return make_error(what + ": a vertex no bone weighs and no joint to move it with");
            w.emplace_back(*s, 1.0);
            if (!part.bones.empty()) ++unweighted;
          }
          std::sort(w.begin(), w.end(), [](const auto& a, const auto& c) { return a.second > c.second; });
          double sum = 0.0, kept = 0.0;
          for (std::size_t i = 0; i < w.size(); ++i) (i < kWeightsPerVertex ? kept : sum) += w[i].second;
          sum += kept;
          if (w.size() > kWeightsPerVertex) ++over_four;
          else if (std::abs(sum - 1.0) > kSkinWeightSumTolerance) ++unnormalized;
          for (std::size_t i = 0; i < std::min(w.size(), kWeightsPerVertex); ++i) {
            joint4[kWeightsPerVertex * v + i] = w[i].first;
            weight4[kWeightsPerVertex * v + i] = static_cast<float>(w[i].second / kept);
          }
        }
        attributes["JOINTS_0"] = integers(joint4, 4, "VEC4", kUnsignedShort);
        attributes["WEIGHTS_0"] = floats(weight4, 4, "VEC4");
      }
      std::vector<std::uint32_t> triangles = part.triangles;
      if (mirrored)
        for (std::size_t k = 0; k < triangles.size(); k += 3) std::swap(triangles[k + 1], triangles[k + 2]);
      json primitive = {{"attributes", attributes}, {"indices", integers(triangles, 1, "SCALAR", kUnsignedInt)}};
      if (part.material >= 0 && static_cast<std::size_t>(part.material) < body.materials.size())
        primitive["material"] = part.material;
      primitives.push_back(primitive);
    }
    if (over_four) note(what + ": " + count_text(over_four, "vertex has", "vertices have") + " more than 4 weights; the 4 heaviest kept, normalized");
    if (unnormalized) note(what + ": " + unnormalized_weights_text(unnormalized) + "; normalized");
    if (unweighted) note(what + ": " + count_text(unweighted, "vertex has", "vertices have") + " no weight; moved with joint '" + mesh.parent_joint + "'");
    meshes_.push_back({{"name", mesh.name}, {"primitives", primitives}});
    ++kept_.meshes;
    json node = {{"name", mesh.name}, {"mesh", meshes_.size() - 1}};
    if (skinned) {
      const std::size_t start = b_.bin.size();
      for (const Eigen::Matrix4d& m : ibms) put_matrix(b_.bin, m);
      json skin = {{"joints", joints}, {"inverseBindMatrices", b_.accessor(start, ibms.size(), "MAT4")}};
      doc_["skins"].push_back(skin);
      node["skin"] = doc_["skins"].size() - 1;
      ++kept_.skins;
      kept_.bones = std::max(kept_.bones, joints.size());
    }
    doc_["nodes"].push_back(node);
    doc_["scenes"][0]["nodes"].push_back(doc_["nodes"].size() - 1);
    return Ok{};
  }

  void note(const std::string& line) { kept_.notes.push_back(line); }

  Builder& b_;
  json& doc_;
  double metres_;
  std::map<std::string, std::size_t> joint_of_;
  std::vector<std::string> names_;  // by joint
  std::vector<Eigen::Matrix4d> joint_world_;
  json meshes_ = json::array(), materials_ = json::array(), images_ = json::array(), textures_ = json::array();
  std::map<int, std::size_t> image_index_;
  BodyKept kept_;
};

}  // namespace

std::string BodyKept::text() const {
  std::vector<std::string> parts;
  if (meshes) parts.push_back(count_text(meshes, "mesh", "meshes"));
  if (skins) parts.push_back(count_text(skins, "skin", "skins") + " (" + count_text(bones, "bone", "bones") + ")");
  if (materials) parts.push_back(count_text(materials, "material", "materials"));
  if (images) parts.push_back(count_text(images, "texture", "textures"));
  return kept_text(parts);
}

Result<BodyKept> add_body(Builder& b, json& doc, const Skeleton& skeleton, double metres, const CharacterBody& body) {
  return BodyWriter(b, doc, skeleton, metres).add(body);
}

}  // namespace rotinterp::gltf
