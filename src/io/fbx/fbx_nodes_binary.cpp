// parse_fbx_binary: binary FBX 6.1–7.7 node records into an FbxDocument, every
// offset and count checked before it is used (io/fbx/fbx_nodes.h states the rules).
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/files/limits.h"
#include "rotinterp/io/files/file_errors.h"

#include <zlib.h>

#include <cstring>
#include <limits>
#include <type_traits>

namespace rotinterp {

namespace {

constexpr std::size_t kHeaderBytes = 27;  // magic (21), 0x1A 0x00, uint32 version
constexpr std::uint32_t kFirstVersion = 6100, kLastVersion = 7700;
constexpr std::uint32_t kWideOffsetsFrom = 7500;  // 64-bit record fields from 7.5 on
// zlib cannot inflate more than 1032 bytes from one; a larger claim is hostile.
constexpr std::uint64_t kZlibMaxRatio = 1032;

class BinaryReader {
 public:
  BinaryReader(std::string_view bytes, const std::string& label, std::uint32_t version)
      : b_(bytes), label_(label), wide_(version >= kWideOffsetsFrom), inflation_(bytes.size()) {}

  // The nodes from `pos` up to `end` (exclusive of their closing null record).
  Status nodes(std::size_t& pos, std::size_t end, std::vector<FbxNode>& out, std::size_t depth) {
    if (depth > kFbxMaxDepth) return fail("nested deeper than " + std::to_string(kFbxMaxDepth) + " levels");
    while (pos < end) {
      std::uint64_t node_end = 0, count = 0, prop_bytes = 0;
      if (!field(pos, end, node_end) || !field(pos, end, count) || !field(pos, end, prop_bytes) || pos >= end)
        return fail("truncated node record");
      const auto name_len = static_cast<unsigned char>(b_[pos++]);
      if (node_end == 0) {  // a null record closes the list
        if (count != 0 || prop_bytes != 0 || name_len != 0) return fail("malformed null record");
        return Ok{};
      }
      if (name_len > end - pos) return fail("truncated node name");
      FbxNode node;
      node.name.assign(b_.data() + pos, name_len);
      pos += name_len;
      path_.push_back(node.name);
      if (node_end <= pos || node_end > end) return fail("end offset " + std::to_string(node_end) + " outside its parent");
      if (prop_bytes > node_end - pos) return fail("property bytes past the node's end");
      const std::size_t props_end = pos + static_cast<std::size_t>(prop_bytes);
      if (count > prop_bytes) return fail(std::to_string(count) + " properties in " + std::to_string(prop_bytes) + " bytes");
      node.properties.reserve(static_cast<std::size_t>(count));
      for (std::uint64_t p = 0; p < count; ++p) {
        FbxProperty prop;
        if (Status s = property(pos, props_end, prop); !s) return s;
        node.properties.push_back(std::move(prop));
      }
      if (pos != props_end) return fail("property bytes do not match the properties");
      const std::size_t children_end = static_cast<std::size_t>(node_end);
      if (pos < children_end) {
        if (Status s = nodes(pos, children_end, node.children, depth + 1); !s) return s;
        pos = children_end;  // past the children's null record
      }
      path_.pop_back();
      out.push_back(std::move(node));
    }
    return Ok{};
  }

  Status fail(const std::string& what) const { return make_error(where() + ": " + what, file_error::unreadable); }

  std::string where() const { return fbx_node_where(label_, path_); }

 private:
  template <class T>
  bool get(std::size_t& pos, std::size_t end, T& v) const {
    if (sizeof(T) > end - pos || pos > end) return false;
    std::memcpy(&v, b_.data() + pos, sizeof(T));  // little-endian host (x86-64, arm64)
    pos += sizeof(T);
    return true;
  }
  bool field(std::size_t& pos, std::size_t end, std::uint64_t& v) const {
    if (wide_) return get(pos, end, v);
    std::uint32_t narrow = 0;
    if (!get(pos, end, narrow)) return false;
    v = narrow;
    return true;
  }

  Status property(std::size_t& pos, std::size_t end, FbxProperty& p) {
    if (pos >= end) return fail("truncated property");
    p.type = b_[pos++];
    bool ok = true;
    switch (p.type) {
      case 'C': { std::uint8_t v = 0; ok = get(pos, end, v); p.integer = v; break; }
      case 'Y': { std::int16_t v = 0; ok = get(pos, end, v); p.integer = v; break; }
      case 'I': { std::int32_t v = 0; ok = get(pos, end, v); p.integer = v; break; }
      case 'L': { std::int64_t v = 0; ok = get(pos, end, v); p.integer = v; break; }
      case 'F': { float v = 0; ok = get(pos, end, v); p.number = v; break; }
      case 'D': { double v = 0; ok = get(pos, end, v); p.number = v; break; }
      case 'S':
      case 'R': {
        std::uint32_t len = 0;
        if (!get(pos, end, len) || len > end - pos) return fail("string property past the node's properties");
        p.text.assign(b_.data() + pos, len);
        pos += len;
        break;
      }
      case 'b': return array<std::uint8_t>(pos, end, p);
      case 'i': return array<std::int32_t>(pos, end, p);
      case 'l': return array<std::int64_t>(pos, end, p);
      case 'f': return array<float>(pos, end, p);
      case 'd': return array<double>(pos, end, p);
      default: return fail(std::string("unknown property type 0x") + hex(p.type));
    }
    if (!ok) return fail("truncated property");
    return Ok{};
  }

  template <class T>
  Status array(std::size_t& pos, std::size_t end, FbxProperty& p) {
    std::uint32_t count = 0, encoding = 0, stored = 0;
    if (!get(pos, end, count) || !get(pos, end, encoding) || !get(pos, end, stored)) return fail("truncated array header");
    if (stored > end - pos) return fail("array of " + std::to_string(stored) + " bytes past the node's properties");
    const std::uint64_t raw_bytes = std::uint64_t{count} * sizeof(T);
    std::string inflated;
    const char* data = b_.data() + pos;
    if (encoding == 0) {
      if (Status s = check_declared_count(count, sizeof(T), stored, kFbxMaxArrayElements, where()); !s) return s;
      if (stored != raw_bytes)
        return fail("array of " + std::to_string(count) + " elements stored in " + std::to_string(stored) + " bytes");
    } else if (encoding == 1) {
      // The count bounds the inflation (uncompress stops there), and the count is
      // bounded by what the stored bytes and the file's size can hold.
      if (Status s = check_declared_count(count, sizeof(T), std::uint64_t{stored} * kZlibMaxRatio, kFbxMaxArrayElements,
                                          where() + " (zlib array)");
          !s)
        return s;
      if (Status s = inflation_.take(std::uint64_t{count} * sizeof(double), where()); !s) return s;
      inflated.resize(static_cast<std::size_t>(raw_bytes));
      uLongf out_len = static_cast<uLongf>(raw_bytes);
      const int rc = ::uncompress(reinterpret_cast<Bytef*>(inflated.data()), &out_len,
                                  reinterpret_cast<const Bytef*>(data), stored);
      if (rc != Z_OK || out_len != raw_bytes) return fail("zlib array does not inflate to its " + std::to_string(count) + " elements");
      data = inflated.data();
    } else {
      return fail("unknown array encoding " + std::to_string(encoding));
    }
    pos += stored;
    if constexpr (std::is_floating_point_v<T>) {
      p.numbers.resize(count);
      for (std::size_t i = 0; i < count; ++i) {
        T v;
        std::memcpy(&v, data + i * sizeof(T), sizeof(T));
        p.numbers[i] = static_cast<double>(v);
      }
    } else {
      p.integers.resize(count);
      for (std::size_t i = 0; i < count; ++i) {
        T v;
        std::memcpy(&v, data + i * sizeof(T), sizeof(T));
        p.integers[i] = static_cast<std::int64_t>(v);
      }
    }
    return Ok{};
  }

  static std::string hex(char c) {
    static const char digits[] = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(c);
    return {digits[u >> 4], digits[u & 15]};
  }

  std::string_view b_;
  const std::string& label_;
  bool wide_;
  InflationBudget inflation_;  // what the file's zlib arrays may inflate to together
  std::vector<std::string> path_;
};

}  // namespace

Result<FbxDocument> parse_fbx_binary(std::string_view bytes, const std::string& label) {
  if (!is_binary_fbx(bytes) || bytes.size() < kHeaderBytes)
    return make_error(label + ": not a binary FBX file (no header)", file_error::unreadable);
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 23, 4);
  if (version < kFirstVersion || version > kLastVersion)
    return make_error(label + ": binary FBX version " + std::to_string(version) + " is not read (6100 to 7700 are)",
                      file_error::unreadable);
  FbxDocument doc;
  doc.binary = true;
  doc.version = version;
  BinaryReader reader(bytes, label, version);
  std::size_t pos = kHeaderBytes;
  if (Status s = reader.nodes(pos, bytes.size(), doc.nodes, 0); !s) return s.failure();
  return doc;
}

}  // namespace rotinterp
