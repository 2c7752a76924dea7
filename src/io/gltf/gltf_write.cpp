// Our glTF 2.0 writer: nodes, skin and animation samplers as .glb or .gltf with its buffer.
#include "rotinterp/io/gltf/gltf_write.h"

#include "gltf_body.h"
#include "gltf_document.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/little_endian.h"
#include "rotinterp/io/files/written_names.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <cstring>
#include <optional>

namespace rotinterp {

namespace gltf {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

struct Document {
  nlohmann::json json;
  std::string buffer;
  BodyKept body;
};

// Inverse bind matrices: the inverse of each joint's world rest transform, column-major,
// its translation in metres (`metres` per clip unit).
std::vector<double> rest_world_inverse(const Skeleton& sk, double metres) {
  const WorldPose rest = rest_pose(sk);  // forward kinematics of the rest pose
  std::vector<double> out;
  for (std::size_t j = 0; j < sk.joints.size(); ++j) {
    const Mat3 rt = rest.rotation[j].toRotationMatrix().transpose();
    Eigen::Matrix4d inv = Eigen::Matrix4d::Identity();  // [R p]⁻¹ = [Rᵀ −Rᵀp]
    inv.topLeftCorner<3, 3>() = rt;
    inv.topRightCorner<3, 1>() = -rt * rest.position[j] * metres;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) out.push_back(inv(r, c));  // column-major
  }
  return out;
}

// The document of the takes' skeleton (the first's: every take has it) with one
// animation per take, in order.
Result<Document> build(const std::vector<const Clip*>& takes, const GltfKeys& keys, const CharacterBody* body = nullptr) {
  for (const Clip* take : takes)
    if (Status s = take->validate(); !s)
      return s.failure(takes.size() > 1 ? "take '" + take->name + "': cannot write an invalid clip: " : "cannot write an invalid clip: ");
  const Clip& clip = *takes.front();
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  if ((keys.cubic_rotations || keys.cubic_translations) && !keys.own_times)
    return make_error("CUBICSPLINE samplers need each track at its own key times");
  // glTF's unit is the metre: translations are converted with the clip's unit scale
  // (an FBX in centimetres keeps its real size; BVH, which has none, is taken as is).
  const double metres = metres_per_unit(clip);
  JointTargets targets;
  for (std::size_t j = 0; j < n; ++j) targets.node.push_back(j);
  targets.translation_scale.assign(n, metres);
  Builder b;

  nlohmann::json nodes = nlohmann::json::array(), roots = nlohmann::json::array();
  std::vector<nlohmann::json> children(n, nlohmann::json::array());
  for (std::size_t j = 0; j < n; ++j) {
    const int p = sk.joints[j].parent;
    if (p < 0) roots.push_back(j);
    else children[static_cast<std::size_t>(p)].push_back(j);
  }
  const std::vector<std::string> names = written_joint_names(sk, NameForm::text);
  for (std::size_t j = 0; j < n; ++j) {
    const Joint& joint = sk.joints[j];
    const Quat r = joint.rest_rotation.normalized();
    nlohmann::json node = {{"name", names[j]},
                           {"translation", {joint.offset.x() * metres, joint.offset.y() * metres, joint.offset.z() * metres}},
                           {"rotation", {r.x(), r.y(), r.z(), r.w()}}};
    if (!children[j].empty()) node["children"] = children[j];
    nodes.push_back(node);
  }
  nlohmann::json animations = nlohmann::json::array();
  for (const Clip* take : takes) {
    Result<nlohmann::json> a = animation(b, *take, keys, targets);
    if (!a) return takes.size() > 1 ? a.failure("take '" + take->name + "': ") : a.failure();
    animations.push_back(std::move(*a));
  }
  const std::size_t start = b.bin.size();
  for (double v : rest_world_inverse(sk, metres)) put_float(b.bin, v);
  const int ibm = b.accessor(start, n, "MAT4");

  nlohmann::json joints = nlohmann::json::array();
  for (std::size_t j = 0; j < n; ++j) joints.push_back(j);
  nlohmann::json skin = {{"name", "skeleton"}, {"joints", joints}, {"inverseBindMatrices", ibm}};
  if (roots.size() == 1) skin["skeleton"] = roots[0];
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}, {"generator", std::string("rotinterp ") + ROTINTERP_VERSION}}},
      {"scene", 0},
      {"scenes", {{{"nodes", roots}}}},
      {"nodes", nodes},
      {"skins", {skin}},
      {"animations", animations},
      {"bufferViews", b.views},
      {"accessors", b.accessors}};
  BodyKept kept;
  if (body) {
    Result<BodyKept> added = add_body(b, doc, sk, metres, *body);
    if (!added) return added.failure();
    kept = std::move(*added);
    doc["bufferViews"] = b.views;
    doc["accessors"] = b.accessors;
  }
  return Document{std::move(doc), std::move(b.bin), std::move(kept)};
}

// The buffer an existing .gltf at `path` names, when it is one this writer named
// (STEM-<16 hex>.bin beside it): a re-run replaces it instead of leaving it behind.
// Anything else (no file, another writer's .gltf, a shared buffer name) is left alone.
std::optional<std::filesystem::path> previous_buffer(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  const nlohmann::json old = nlohmann::json::parse(in, nullptr, false);
  if (old.is_discarded() || !old.contains("buffers") || !old["buffers"].is_array() || old["buffers"].size() != 1)
    return std::nullopt;
  const nlohmann::json& uri = old["buffers"][0]["uri"];
  if (!uri.is_string()) return std::nullopt;
  const std::string name = uri.get<std::string>(), stem = path.stem().string() + "-";
  if (name.size() != stem.size() + 16 + 4 || name.compare(0, stem.size(), stem) != 0 ||
      name.compare(name.size() - 4, 4, ".bin") != 0)
    return std::nullopt;
  for (std::size_t i = stem.size(); i < stem.size() + 16; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return std::nullopt;
  return std::filesystem::path(path).replace_filename(name);
}

}  // namespace

Status write_document(nlohmann::json doc, std::string bin, const std::filesystem::path& path, bool binary) {
  const std::string label = path.string();
  doc["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}}});
  if (binary) {
    std::string json = json_text(doc);
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    const std::uint64_t total = 12 + 8 + json.size() + 8 + bin.size();
    if (total > UINT32_MAX) return make_error(label + ": the GLB would pass 4 GiB; write .gltf instead");
    return write_file_atomically(path, [&](std::ostream& out) -> Status {
      std::string head;
      put_le(head, kGlbMagic);
      put_le<std::uint32_t>(head, 2);
      put_le(head, static_cast<std::uint32_t>(total));
      put_le(head, static_cast<std::uint32_t>(json.size()));
      put_le(head, kChunkJson);
      out << head << json;
      head.clear();
      put_le(head, static_cast<std::uint32_t>(bin.size()));
      put_le(head, kChunkBin);
      out << head << bin;
      return Ok{};
    });
  }
  // The buffer is named by its bytes: a .gltf never names a buffer another run
  // wrote. Both are written and synced to temporaries first, then committed
  // together (buffer first), so a failure leaves the previous pair as it was; once
  // the new pair is in place, the buffer the replaced .gltf named is removed.
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(bin)));
  const std::filesystem::path bin_path = std::filesystem::path(path).replace_filename(path.stem().string() + "-" + hash + ".bin");
  // The uri is JSON text: a file name it cannot hold is refused here, not by nlohmann.
  if (readable_text(bin_path.filename().string()) != bin_path.filename().string())
    return make_error(label + ": a .gltf names its buffer after itself, and this name is not valid UTF-8 free of "
                      "control characters; write .glb or choose another name");
  doc["buffers"][0]["uri"] = bin_path.filename().string();
  const std::string json = json_text(doc);
  // Named temporaries, removed by the interrupt handler (as assimp-era .gltf writes were).
  // Their errors name their own file (the .bin beside the .gltf, or the folder).
  AtomicOutput bin_out(bin_path), gltf_out(path);
  if (Status s = bin_out.write(bin.data(), bin.size()); !s) return s;
  if (Status s = gltf_out.write(json.data(), json.size()); !s) return s;
  if (Status s = bin_out.finish(); !s) return s;
  if (Status s = gltf_out.finish(); !s) return s;
  const std::optional<std::filesystem::path> old_bin = previous_buffer(path);
  if (Status s = commit_together({&bin_out, &gltf_out}); !s) return s;
  std::error_code ec;
  if (old_bin && *old_bin != bin_path) std::filesystem::remove(*old_bin, ec);  // a leftover at worst
  return Ok{};
}

}  // namespace gltf

Status write_gltf(const Clip& clip, const std::filesystem::path& path, bool binary, const GltfKeys& keys) {
  return write_gltf(std::vector<const Clip*>{&clip}, path, binary, keys);
}

Status write_gltf(const std::vector<const Clip*>& takes, const std::filesystem::path& path, bool binary,
                  const GltfKeys& keys) {
  if (takes.empty()) return make_error(path.string() + ": no takes to write");
  Result<gltf::Document> doc = gltf::build(takes, keys);
  if (!doc) return doc.failure(path.string() + ": ");
  return gltf::write_document(std::move(doc->json), std::move(doc->buffer), path, binary);
}

Result<GltfBodyWritten> write_gltf(const std::vector<const Clip*>& takes, const std::filesystem::path& path, bool binary,
                                   const GltfKeys& keys, const CharacterBody& body) {
  if (takes.empty()) return make_error(path.string() + ": no takes to write");
  Result<gltf::Document> doc = gltf::build(takes, keys, &body);
  if (!doc) return doc.failure(path.string() + ": ");
  if (Status s = gltf::write_document(std::move(doc->json), std::move(doc->buffer), path, binary); !s) return s.failure();
  return GltfBodyWritten{doc->body.text(), std::move(doc->body.notes)};
}

}  // namespace rotinterp
