// read_gltf_animations: a .glb or .gltf file's nodes and rotation/translation samplers,
// by our own reader (assimp keeps neither the interpolation nor the tangents). Every
// number taken from the file is checked before it indexes anything: the file is input.
#include "rotinterp/io/gltf/gltf_source.h"

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

using nlohmann::json;

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kGlbHeader = 12, kChunkHeader = 8;

// Component types (the spec's accessor.componentType).
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kFloat = 5126;

std::uint32_t u32_at(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
}

struct Container {
  std::string_view json;
  std::optional<std::string_view> bin;  // GLB: its BIN chunk (buffer 0 without a uri)
};

Result<Container> split_container(std::string_view bytes, const std::string& label) {
  if (bytes.size() < 4 || u32_at(bytes, 0) != kGlbMagic) return Container{bytes, std::nullopt};
  if (bytes.size() < kGlbHeader + kChunkHeader) return make_error(label + ": a GLB shorter than its header");
  if (u32_at(bytes, 4) != 2) return make_error(label + ": GLB version " + std::to_string(u32_at(bytes, 4)) + ", not 2");
  const std::size_t length = std::min<std::size_t>(u32_at(bytes, 8), bytes.size());
  if (length < kGlbHeader + kChunkHeader) return make_error(label + ": a GLB whose declared length is below its header's");
  const std::size_t json_length = u32_at(bytes, kGlbHeader);
  if (u32_at(bytes, kGlbHeader + 4) != kGlbJsonChunk || json_length > length - kGlbHeader - kChunkHeader)
    return make_error(label + ": the GLB's first chunk is not its JSON, or passes the file's end");
  Container out{bytes.substr(kGlbHeader + kChunkHeader, json_length), std::nullopt};
  const std::size_t bin_at = kGlbHeader + kChunkHeader + json_length;
  if (length - bin_at >= kChunkHeader && u32_at(bytes, bin_at + 4) == kGlbBinChunk) {
    const std::size_t bin_length = u32_at(bytes, bin_at);
    if (bin_length > length - bin_at - kChunkHeader) return make_error(label + ": the GLB's BIN chunk passes the file's end");
    out.bin = bytes.substr(bin_at + kChunkHeader, bin_length);
  }
  return out;
}

Result<std::string> decode_base64(std::string_view text) {
  std::string out;
  std::uint32_t bits = 0;
  int held = 0;
  for (char ch : text) {
    int v;
    if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
    else if (ch == '+') v = 62;
    else if (ch == '/') v = 63;
    else if (ch == '=') break;
    else return make_error("a data: URI is not base64");
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    if ((held += 6) >= 8) {
      held -= 8;
      out.push_back(static_cast<char>((bits >> held) & 0xff));
    }
  }
  return out;
}

// A URI's %XX escapes decoded (glTF URIs are RFC 3986 references).
std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

// A whole number ≥ 0 that the spec requires (indices, offsets, lengths, counts).
std::uint64_t whole(const json& object, const char* key, std::optional<std::uint64_t> fallback = std::nullopt) {
  if (!object.contains(key)) {
    if (fallback) return *fallback;
    throw std::runtime_error(std::string("missing \"") + key + "\"");
  }
  const json& v = object.at(key);
  if (!v.is_number_unsigned()) throw std::runtime_error(std::string("\"") + key + "\" is not a whole number");
  return v.get<std::uint64_t>();
}

const json& element(const json& doc, const char* array, std::uint64_t index) {
  if (!doc.contains(array) || !doc.at(array).is_array() || index >= doc.at(array).size())
    throw std::runtime_error(std::string(array) + " " + std::to_string(index) + " does not exist");
  return doc.at(array).at(index);
}

// The file's buffers, read when first used. Errors throw (caught once, in parse).
class Buffers {
 public:
  Buffers(const json& doc, const Container& file, std::filesystem::path folder, bool allow_external_files)
      : doc_(doc), file_(file), folder_(std::move(folder)), allow_external_files_(allow_external_files) {}

  std::string_view bytes(std::uint64_t index) {
    auto it = loaded_.find(index);
    if (it == loaded_.end()) it = loaded_.emplace(index, load(index)).first;
    return it->second;
  }

 private:
  std::string load(std::uint64_t index) {
    const json& buffer = element(doc_, "buffers", index);
    const std::uint64_t length = whole(buffer, "byteLength");
    std::string data;
    const std::string name = "buffer " + std::to_string(index);
    if (!buffer.contains("uri")) {
      if (index != 0 || !file_.bin) throw std::runtime_error(name + " has no uri and no GLB BIN chunk");
      data = std::string(*file_.bin);
    } else if (const std::string uri = buffer.at("uri").get<std::string>(); uri.rfind("data:", 0) == 0) {
      const std::size_t comma = uri.find(',');
      if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
        throw std::runtime_error(name + ": only base64 data: URIs are read");
      auto decoded = decode_base64(std::string_view(uri).substr(comma + 1));
      if (!decoded) throw std::runtime_error(name + ": " + decoded.error());
      data = std::move(*decoded);
    } else {
      // A file beside the .gltf (others with allow_external_files), a regular one; no other scheme.
      const std::string what = name + ": uri '" + uri + "'";
      if (uri.find(':') != std::string::npos && !allow_external_files_)
        throw std::runtime_error(what + " is not a relative file in the file's folder");
      auto file = referenced_file(folder_, percent_decoded(uri), allow_external_files_, what);
      if (!file) throw std::runtime_error(file.error());
      // A buffer file's size is checked before it is read: byteLength must fit in it.
      std::error_code ec;
      const std::uintmax_t size = std::filesystem::file_size(*file, ec);
      if (!ec && length > size)
        throw std::runtime_error(name + " declares " + std::to_string(length) + " bytes and holds " + std::to_string(size));
      auto read = read_input_file(*file, what);
      if (!read) throw std::runtime_error(read.error());
      data = std::move(*read);
    }
    if (length > data.size())
      throw std::runtime_error(name + " declares " + std::to_string(length) + " bytes and holds " +
                               std::to_string(data.size()));
    data.resize(static_cast<std::size_t>(length));
    return data;
  }

  const json& doc_;
  const Container& file_;
  std::filesystem::path folder_;
  bool allow_external_files_;
  std::map<std::uint64_t, std::string> loaded_;
};

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
    const std::size_t nodes = doc.contains("nodes") ? doc.at("nodes").size() : 0;
    for (std::size_t i = 0; i < nodes; ++i) {
      const std::string name = doc.at("nodes").at(i).value("name", std::string());
      out.node_names.push_back(name.empty() ? "nodes_" + std::to_string(i) : name);  // assimp's GetNodeName
    }
    Buffers buffers(doc, *file, folder, allow_external_files);
    if (doc.contains("animations"))
      for (const json& animation : doc.at("animations")) out.animations.push_back(read_animation(doc, buffers, animation, nodes, out.repairs));
    return out;
  } catch (const std::exception& e) {
    return make_error(label + ": glTF animations: " + e.what(), file_error::unreadable);
  }
}

Result<GltfAnimations> read_gltf_animations(const std::filesystem::path& path, bool allow_external_files) {
  auto bytes = read_input_file(path, path.string());
  if (!bytes) return bytes.failure();
  return parse_gltf_animations(*bytes, path.parent_path(), path.string(), allow_external_files);
}

}  // namespace rotinterp
