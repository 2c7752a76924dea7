// The glTF file as stored: GLB chunks, buffers and the checked lookups (gltf_container.h).
#include "gltf_container.h"

#include "rotinterp/io/files/input_file.h"

#include <cctype>
#include <stdexcept>

namespace rotinterp::gltf {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kGlbHeader = 12, kChunkHeader = 8;

std::uint32_t u32_at(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
  return v;
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

}  // namespace

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

std::uint64_t whole(const json& object, const char* key, std::optional<std::uint64_t> fallback) {
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

std::vector<std::string> node_names(const json& doc) {
  std::vector<std::string> out;
  if (!doc.contains("nodes") || !doc.at("nodes").is_array()) return out;
  for (std::size_t i = 0; i < doc.at("nodes").size(); ++i) {
    const json& node = doc.at("nodes").at(i);
    const std::string name = node.is_object() ? node.value("name", std::string()) : std::string();
    out.push_back(name.empty() ? "nodes_" + std::to_string(i) : name);
  }
  return out;
}

std::string_view Buffers::bytes(std::uint64_t index) {
  auto it = loaded_.find(index);
  if (it == loaded_.end()) it = loaded_.emplace(index, load(index)).first;
  return it->second;
}

std::string Buffers::load(std::uint64_t index) {
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

}  // namespace rotinterp::gltf
