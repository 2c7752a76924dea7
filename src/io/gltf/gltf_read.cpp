// read_gltf_animations: a .glb or .gltf file's nodes and rotation/translation samplers,
// by our own reader (assimp keeps neither the interpolation nor the tangents). Every
// number taken from the file is checked before it indexes anything: the file is input.
#include "rotinterp/io/gltf/gltf_source.h"

#include "gltf_container.h"
#include "rotinterp/io/files/input_file.h"
#include "rotinterp/io/files/key_checks.h"
#include "rotinterp/io/files/file_errors.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>

namespace rotinterp {

namespace {

using namespace gltf;

// Component types (the spec's accessor.componentType).
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kFloat = 5126;

std::size_t component_size(int type) { return type == kFloat ? 4 : type == kShort || type == kUnsignedShort ? 2 : 1; }

// One component at `p`, normalized integers mapped to [-1, 1] or [0, 1] as the spec says.
double component(const char* p, int type) {
  switch (type) {
    case kFloat: {
      std::uint32_t u = 0;
      for (int i = 3; i >= 0; --i) u = (u << 8) | static_cast<unsigned char>(p[i]);
      float f;
      std::memcpy(&f, &u, 4);
      return f;
    }
    case kByte: return std::max(static_cast<signed char>(p[0]) / 127.0, -1.0);
    case kUnsignedByte: return static_cast<unsigned char>(p[0]) / 255.0;
    case kShort: {
      const auto v = static_cast<std::int16_t>(static_cast<unsigned char>(p[0]) | (static_cast<unsigned char>(p[1]) << 8));
      return std::max(v / 32767.0, -1.0);
    }
    default: return (static_cast<unsigned char>(p[0]) | (static_cast<unsigned char>(p[1]) << 8)) / 65535.0;
  }
}

// Accessor `index` as doubles, `width` components per element: float, or (where
// `quantized`) the normalized integer types the spec allows for rotations.
std::vector<double> read_accessor(const json& doc, Buffers& buffers, std::uint64_t index, std::size_t width,
                                  bool quantized) {
  const json& accessor = element(doc, "accessors", index);
  const std::string name = "accessor " + std::to_string(index);
  if (accessor.contains("sparse")) throw std::runtime_error(name + " is sparse (not read)");
  const std::string type = accessor.at("type").get<std::string>();
  if (type != (width == 1 ? "SCALAR" : width == 3 ? "VEC3" : "VEC4"))
    throw std::runtime_error(name + " is " + type + " where " + std::to_string(width) + " components are needed");
  const int ctype = accessor.at("componentType").get<int>();
  const bool integer = ctype == kByte || ctype == kUnsignedByte || ctype == kShort || ctype == kUnsignedShort;
  if (ctype != kFloat && !(quantized && integer && accessor.value("normalized", false)))
    throw std::runtime_error(name + ": component type " + std::to_string(ctype) + " is not allowed here");
  const std::uint64_t count = whole(accessor, "count");
  if (count == 0) throw std::runtime_error(name + " has no element");
  if (!accessor.contains("bufferView")) return std::vector<double>(count * width, 0.0);  // zeros, as the spec says
  const json& view = element(doc, "bufferViews", whole(accessor, "bufferView"));
  const std::string_view buffer = buffers.bytes(whole(view, "buffer"));
  const std::uint64_t view_offset = whole(view, "byteOffset", 0), view_length = whole(view, "byteLength");
  if (view_offset > buffer.size() || view_length > buffer.size() - view_offset)
    throw std::runtime_error(name + ": its buffer view passes its buffer's end");
  const std::uint64_t element_size = width * component_size(ctype);
  const std::uint64_t stride = whole(view, "byteStride", element_size), offset = whole(accessor, "byteOffset", 0);
  // count ≤ view_length (each element ≥ 1 byte) and stride < 256 keep the product far from overflow.
  if (stride < element_size || stride > 255 || count > view_length || offset > view_length ||
      stride * (count - 1) + element_size > view_length - offset)
    throw std::runtime_error(name + ": " + std::to_string(count) + " elements of " + std::to_string(stride) +
                             " bytes pass its buffer view (" + std::to_string(view_length) + " bytes)");
  std::vector<double> out;
  out.reserve(count * width);
  const char* base = buffer.data() + view_offset + offset;
  for (std::uint64_t e = 0; e < count; ++e)
    for (std::size_t c = 0; c < width; ++c) out.push_back(component(base + e * stride + c * component_size(ctype), ctype));
  return out;
}

// The sampler's keys through the shared pass (io/files/key_checks.h): repeated keys
// dropped (a line in `repairs`), rotations of no length refused. `where` names it.
GltfSampler read_sampler(const json& doc, Buffers& buffers, const json& sampler, std::size_t width,
                         const std::string& where, std::vector<std::string>& repairs) {
  GltfSampler out;
  const std::string how = sampler.value("interpolation", std::string("LINEAR"));
  if (how == "LINEAR") out.interpolation = GltfInterpolation::linear;
  else if (how == "STEP") out.interpolation = GltfInterpolation::step;
  else if (how == "CUBICSPLINE") out.interpolation = GltfInterpolation::cubic_spline;
  else throw std::runtime_error("unknown interpolation '" + how + "'");
  out.width = width;
  out.times = read_accessor(doc, buffers, whole(sampler, "input"), 1, false);
  out.values = read_accessor(doc, buffers, whole(sampler, "output"), width, width == 4);
  const bool cubic = out.interpolation == GltfInterpolation::cubic_spline;
  const std::size_t per_key = width * (cubic ? 3 : 1);
  if (out.values.size() == out.times.size() * per_key) {
    Result<std::vector<std::size_t>> repaired = check_keys(out.times, out.values, per_key, where);
    if (!repaired) throw std::runtime_error(repaired.error());
    drop_keys(out.times, *repaired, 1);
    drop_keys(out.values, *repaired, per_key);
    if (!repaired->empty()) repairs.push_back(repaired_keys_warning(where, repaired->size()));
    // A CUBICSPLINE key is (in-tangent, value, out-tangent): only the value is a rotation.
    if (width == 4)
      if (Status q = check_quaternion_keys(out.values, cubic ? width : 0, per_key, where); !q)
        throw std::runtime_error(q.error());
  }
  if (Status s = validate_gltf_sampler(out); !s) throw std::runtime_error(where + ": " + s.error());
  return out;
}

GltfAnimation read_animation(const json& doc, Buffers& buffers, const json& animation, std::size_t nodes,
                             std::vector<std::string>& repairs) {
  GltfAnimation out;
  out.name = animation.value("name", std::string());
  out.nodes.assign(nodes, {});
  std::map<std::uint64_t, int> decoded;  // sampler index in the file → in out.samplers
  for (const json& channel : animation.at("channels")) {
    const json& target = channel.at("target");
    const std::string path = target.at("path").get<std::string>();
    if (!target.contains("node") || (path != "rotation" && path != "translation")) continue;
    const std::uint64_t node = whole(target, "node");
    if (node >= nodes) throw std::runtime_error("a channel targets node " + std::to_string(node) + ", which does not exist");
    const std::uint64_t index = whole(channel, "sampler");
    const std::size_t width = path == "rotation" ? 4 : 3;
    // Keyed by width too: one sampler read both ways is malformed and refused by the type check.
    auto [it, fresh] = decoded.emplace(index * 8 + width, static_cast<int>(out.samplers.size()));
    if (fresh) {
      if (!animation.contains("samplers") || index >= animation.at("samplers").size())
        throw std::runtime_error("a channel uses sampler " + std::to_string(index) + ", which does not exist");
      const std::string where = "animation '" + out.name + "' sampler " + std::to_string(index) + " (node " +
                                std::to_string(node) + " " + path + ")";
      out.samplers.push_back(read_sampler(doc, buffers, animation.at("samplers").at(index), width, where, repairs));
    }
    // A later channel on the same node and path replaces an earlier one, as assimp's importer does.
    (path == "rotation" ? out.nodes[node].rotation : out.nodes[node].translation) = it->second;
  }
  return out;
}

}  // namespace

Result<GltfAnimations> parse_gltf_animations(std::string_view bytes, const std::filesystem::path& folder,
                                             const std::string& label, bool allow_external_files) {
  auto file = split_container(bytes, label);
  if (!file) return file.failure();
  const json doc = json::parse(file->json.begin(), file->json.end(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return make_error(label + ": its glTF JSON does not parse");
  try {
    GltfAnimations out;
    out.node_names = node_names(doc);
    const std::size_t nodes = out.node_names.size();
    Buffers buffers(doc, *file, folder, allow_external_files);
    if (doc.contains("animations"))
      for (const json& animation : doc.at("animations")) out.animations.push_back(read_animation(doc, buffers, animation, nodes, out.repairs));
    return out;
  } catch (const std::exception& e) {
    return make_error(label + ": glTF animations: " + e.what(), file_error::unreadable);
  }
}

std::vector<int> gltf_node_of_joints(const Skeleton& skeleton, const std::vector<std::string>& node_names) {
  std::map<std::string, int> node;
  for (std::size_t i = 0; i < node_names.size(); ++i) {
    auto [it, fresh] = node.emplace(node_names[i], static_cast<int>(i));
    if (!fresh) it->second = -1;
  }
  std::vector<int> out;
  for (const Joint& joint : skeleton.joints) {
    const auto it = node.find(joint.name);
    out.push_back(it == node.end() ? -1 : it->second);
  }
  return out;
}

Result<GltfAnimations> read_gltf_animations(const std::filesystem::path& path, bool allow_external_files) {
  auto bytes = read_input_file(path, path.string());
  if (!bytes) return bytes.failure();
  return parse_gltf_animations(*bytes, path.parent_path(), path.string(), allow_external_files);
}

}  // namespace rotinterp
