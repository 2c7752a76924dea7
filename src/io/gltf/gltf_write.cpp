// Our glTF 2.0 writer: nodes, skin and animation samplers as .glb or .gltf with its buffer.
#include "rotinterp/io/gltf/gltf_write.h"

#include "rotinterp/io/files/little_endian.h"

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/interp/gltf_cubic.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/key_times.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/track/sample.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <cstring>
#include <optional>

namespace rotinterp {

namespace {

constexpr int kFloat = 5126;            // glTF componentType FLOAT
constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

void put_float(std::string& out, double v) { put_le(out, bits(static_cast<float>(v))); }

// The buffer and the accessors into it: one buffer view per accessor.
struct Builder {
  std::string bin;
  nlohmann::json views = nlohmann::json::array();
  nlohmann::json accessors = nlohmann::json::array();

  // Floats already appended from `start`; `count` elements of `type` ("VEC4", …).
  int accessor(std::size_t start, std::size_t count, const char* type, nlohmann::json extra = nlohmann::json::object()) {
    views.push_back({{"buffer", 0}, {"byteOffset", start}, {"byteLength", bin.size() - start}});
    nlohmann::json a = {{"bufferView", views.size() - 1}, {"componentType", kFloat}, {"count", count}, {"type", type}};
    a.update(extra);
    accessors.push_back(a);
    return static_cast<int>(accessors.size() - 1);
  }
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

std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

struct Document {
  nlohmann::json json;
  std::string buffer;
};

// A sampler input: the times as floats, with their min and max.
int time_accessor(Builder& b, const std::vector<double>& times) {
  const std::size_t start = b.bin.size();
  float lo = INFINITY, hi = -INFINITY;
  for (double t : times) {
    put_float(b.bin, t);
    lo = std::min(lo, static_cast<float>(t));
    hi = std::max(hi, static_cast<float>(t));
  }
  return b.accessor(start, times.size(), "SCALAR", {{"min", {lo}}, {"max", {hi}}});
}

void put_vec4(std::string& bin, const Eigen::Vector4d& v) {
  for (int c = 0; c < 4; ++c) put_float(bin, v[c]);
}

// The samplers of one joint's own keys (GltfKeys::own_times): (input, output,
// interpolation) for its rotation and, if any, its translation.
struct OwnSampler {
  int input, output;
  const char* interpolation;
  const char* path;
};
Result<std::vector<OwnSampler>> own_samplers(Builder& b, const Clip& clip, std::size_t j, const GltfKeys& keys, double metres) {
  std::vector<OwnSampler> out;
  const RotationTrack& rt = clip.rotations[j];
  const int rin = time_accessor(b, rt.times);
  std::size_t start = b.bin.size();
  if (keys.cubic_rotations) {
    // Each key as (in-tangent, value, out-tangent); ours are one tangent per key.
    auto k = gltf_cubic_keys(rt);
    if (!k) return k.failure("joint '" + clip.skeleton.joints[j].name + "': ");
    for (std::size_t i = 0; i < k->keys.size(); ++i) {
      put_vec4(b.bin, k->tangents[i]);
      put_vec4(b.bin, k->keys[i].coeffs());
      put_vec4(b.bin, k->tangents[i]);
    }
    out.push_back({rin, b.accessor(start, 3 * k->keys.size(), "VEC4"), "CUBICSPLINE", "rotation"});
  } else {
    Quat previous = rt.keys.front();
    for (Quat q : rt.keys) {
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      put_vec4(b.bin, q.coeffs());
    }
    out.push_back({rin, b.accessor(start, rt.keys.size(), "VEC4"), "LINEAR", "rotation"});
  }
  if (const auto& tr = clip.translations[j]) {
    const int tin = tr->times == rt.times ? rin : time_accessor(b, tr->times);
    start = b.bin.size();
    auto put3 = [&](const Vec3& v) {
      for (int a = 0; a < 3; ++a) put_float(b.bin, v[a] * metres);
    };
    if (keys.cubic_translations) {
      const TranslationCurve curve(*tr, TranslationInterp::cubic);
      for (std::size_t i = 0; i < tr->keys.size(); ++i) {
        const Vec3 m = curve.tangents().empty() ? Vec3::Zero() : curve.tangents()[i];
        put3(m);
        put3(tr->keys[i]);
        put3(m);
      }
      out.push_back({tin, b.accessor(start, 3 * tr->keys.size(), "VEC3"), "CUBICSPLINE", "translation"});
    } else {
      for (const Vec3& v : tr->keys) put3(v);
      out.push_back({tin, b.accessor(start, tr->keys.size(), "VEC3"), "LINEAR", "translation"});
    }
  }
  return out;
}

// One animation: per joint its rotation sampler (and translation sampler), its
// samplers' accessors appended to the buffer in joint order.
Result<nlohmann::json> animation(Builder& b, const Clip& clip, const GltfKeys& keys) {
  const std::vector<double> times = keys.own_times ? std::vector<double>{} : all_key_times(clip);
  // glTF's unit is the metre: translations are converted with the clip's unit scale
  // (an FBX in centimetres keeps its real size; BVH, which has none, is taken as is).
  const double metres = metres_per_unit(clip);
  const int input = keys.own_times ? -1 : time_accessor(b, times);
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    auto channel = [&](int output, const char* path, int in = -1, const char* interpolation = "LINEAR") {
      samplers.push_back({{"input", in < 0 ? input : in}, {"output", output}, {"interpolation", interpolation}});
      channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", j}, {"path", path}}}});
    };
    if (keys.own_times) {
      auto own = own_samplers(b, clip, j, keys, metres);
      if (!own) return own.failure();
      for (const OwnSampler& o : *own) channel(o.output, o.path, o.input, o.interpolation);
      continue;
    }
    std::size_t start = b.bin.size();
    // Sign-continuous keys (the clip's tracks are): no reader takes the long way round.
    Quat previous = sample_rotation(clip.rotations[j], times.front());
    for (double t : times) {
      Quat q = sample_rotation(clip.rotations[j], t);
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      for (double c : {q.x(), q.y(), q.z(), q.w()}) put_float(b.bin, c);
    }
    channel(b.accessor(start, times.size(), "VEC4"), "rotation");
    if (const auto& tr = clip.translations[j]) {
      start = b.bin.size();
      for (double t : times) {
        const Vec3 v = sample_translation(*tr, t);
        for (int a = 0; a < 3; ++a) put_float(b.bin, v[a] * metres);
      }
      channel(b.accessor(start, times.size(), "VEC3"), "translation");
    }
  }
  return nlohmann::json{{"name", clip.name.empty() ? std::string("clip") : readable_text(clip.name)}, {"samplers", samplers}, {"channels", channels}};
}

// The document of the takes' skeleton (the first's: every take has it) with one
// animation per take, in order.
Result<Document> build(const std::vector<const Clip*>& takes, const GltfKeys& keys) {
  for (const Clip* take : takes)
    if (Status s = take->validate(); !s)
      return s.failure(takes.size() > 1 ? "take '" + take->name + "': cannot write an invalid clip: " : "cannot write an invalid clip: ");
  const Clip& clip = *takes.front();
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size();
  if ((keys.cubic_rotations || keys.cubic_translations) && !keys.own_times)
    return make_error("CUBICSPLINE samplers need each track at its own key times");
  const double metres = metres_per_unit(clip);
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
    Result<nlohmann::json> a = animation(b, *take, keys);
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
  const nlohmann::json buffer = {{"byteLength", b.bin.size()}};
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}, {"generator", std::string("rotinterp ") + ROTINTERP_VERSION}}},
      {"scene", 0},
      {"scenes", {{{"nodes", roots}}}},
      {"nodes", nodes},
      {"skins", {skin}},
      {"animations", animations},
      {"buffers", {buffer}},
      {"bufferViews", b.views},
      {"accessors", b.accessors}};
  return Document{std::move(doc), std::move(b.bin)};
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

Status write_gltf(const Clip& clip, const std::filesystem::path& path, bool binary, const GltfKeys& keys) {
  return write_gltf(std::vector<const Clip*>{&clip}, path, binary, keys);
}

Status write_gltf(const std::vector<const Clip*>& takes, const std::filesystem::path& path, bool binary,
                  const GltfKeys& keys) {
  const std::string label = path.string();
  if (takes.empty()) return make_error(label + ": no takes to write");
  Result<Document> doc = build(takes, keys);
  if (!doc) return doc.failure(label + ": ");
  if (binary) {
    std::string json = json_text(doc->json);
    std::string& bin = doc->buffer;
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
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(doc->buffer)));
  const std::filesystem::path bin_path = std::filesystem::path(path).replace_filename(path.stem().string() + "-" + hash + ".bin");
  // The uri is JSON text: a file name it cannot hold is refused here, not by nlohmann.
  if (readable_text(bin_path.filename().string()) != bin_path.filename().string())
    return make_error(label + ": a .gltf names its buffer after itself, and this name is not valid UTF-8 free of "
                      "control characters; write .glb or choose another name");
  doc->json["buffers"][0]["uri"] = bin_path.filename().string();
  const std::string json = json_text(doc->json);
  // Named temporaries, removed by the interrupt handler (as assimp-era .gltf writes were).
  // Their errors name their own file (the .bin beside the .gltf, or the folder).
  AtomicOutput bin_out(bin_path), gltf_out(path);
  if (Status s = bin_out.write(doc->buffer.data(), doc->buffer.size()); !s) return s;
  if (Status s = gltf_out.write(json.data(), json.size()); !s) return s;
  if (Status s = bin_out.finish(); !s) return s;
  if (Status s = gltf_out.finish(); !s) return s;
  const std::optional<std::filesystem::path> old_bin = previous_buffer(path);
  if (Status s = commit_together({&bin_out, &gltf_out}); !s) return s;
  std::error_code ec;
  if (old_bin && *old_bin != bin_path) std::filesystem::remove(*old_bin, ec);  // a leftover at worst
  return Ok{};
}

}  // namespace rotinterp
