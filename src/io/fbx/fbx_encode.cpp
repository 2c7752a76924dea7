// The FBX node tree as binary or ASCII FBX 7.4, written as it is produced.
#include "fbx_encode.h"

#include "rotinterp/io/files/little_endian.h"

#include <zlib.h>

#include <cctype>
#include <charconv>
#include <cstring>
#include <limits>

namespace rotinterp {

namespace {

constexpr std::size_t kNullRecord = 13;  // the 13 zero bytes that close a child list
// zlib when an array's raw bytes pass this (the FBX SDK's own threshold).
constexpr std::size_t kCompressAbove = 128;
// Nodes the FBX SDK always writes as a block, even without children.
constexpr std::string_view kAlwaysBlock[] = {"AnimationStack", "AnimationLayer"};

// Fixed fields of the binary header and footer, as every FBX 7.x file has them
// (readers do not check the footer's content; these are the values the public
// format notes give for the CreationTime below).
constexpr char kMagic[] = "Kaydara FBX Binary  ";  // 20 characters, then \0 \x1A \0
constexpr unsigned char kFooterId[16] = {0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66,
                                         0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
constexpr unsigned char kFooterMagic[16] = {0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e,
                                            0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

void put_u32_at(std::string& out, std::size_t at, std::uint32_t v) {
  for (std::size_t i = 0; i < 4; ++i) out[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}
// A string or raw property's bytes: their length, then them.
void put_sized(std::string& out, std::string_view bytes) {
  put_le(out, static_cast<std::uint32_t>(bytes.size()));
  out.append(bytes);
}

template <class T>
void put_number_text(std::string& out, T v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string quoted(std::string_view s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += "&quot;";
    else if (c == '\n' || c == '\r') q += ' ';
    else q += c;
  }
  return q + "\"";
}

}  // namespace

FbxEncoder::FbxEncoder(Format format) : format_(format) {
  if (format_ == Format::binary) {
    out_.append(kMagic, 20);
    out_.push_back('\0');
    out_.push_back('\x1a');
    out_.push_back('\0');
    put_le<std::uint32_t>(out_, kVersion);
  } else {
    out_ = "; FBX 7.4.0 project file\n; Created by rotinterp\n; ----------------------------------------------------\n\n";
  }
}

std::string FbxEncoder::object_name(std::string_view name, std::string_view cls) const {
  if (format_ == Format::binary) return std::string(name) + std::string("\0\1", 2) + std::string(cls);
  return std::string(cls) + "::" + std::string(name);
}

void FbxEncoder::close_props(Open& node) {
  if (node.children) return;
  node.children = true;
  if (format_ == Format::binary) {
    const std::size_t len = out_.size() - node.props_start;
    if (len > std::numeric_limits<std::uint32_t>::max()) too_large_ = true;
    put_u32_at(out_, node.header + 8, static_cast<std::uint32_t>(len));
  } else {
    out_ += " {\n";
  }
}

void FbxEncoder::begin(std::string_view name) {
  if (!open_.empty()) close_props(open_.back());
  Open node;
  for (std::string_view b : kAlwaysBlock) node.always_block = node.always_block || name == b;
  if (format_ == Format::binary) {
    node.header = out_.size();
    out_.append(12, '\0');  // end offset, property count, property bytes: patched later
    out_.push_back(static_cast<char>(name.size() & 0xff));
    out_.append(name.substr(0, 255));
    node.props_start = out_.size();
  } else {
    out_.append(open_.size(), '\t');
    out_.append(name);
    out_ += ":";
  }
  open_.push_back(node);
}

void FbxEncoder::end() {
  Open node = open_.back();
  const bool had_children = node.children;
  if (format_ == Format::binary) {
    if (!had_children) {
      close_props(node);  // patches the property byte count
      node.children = false;
    }
    if (had_children || node.props == 0 || node.always_block) out_.append(kNullRecord, '\0');
    if (out_.size() > std::numeric_limits<std::uint32_t>::max()) too_large_ = true;
    put_u32_at(out_, node.header, static_cast<std::uint32_t>(out_.size()));
    put_u32_at(out_, node.header + 4, node.props);
    open_.pop_back();
    return;
  }
  open_.pop_back();
  if (had_children) {
    out_.append(open_.size(), '\t');
    out_ += "}\n";
  } else if (node.props == 0 || node.always_block) {
    out_ += " {\n";
    out_.append(open_.size(), '\t');
    out_ += "}\n";
  } else {
    out_ += "\n";
  }
}

void FbxEncoder::before_prop(char type) {
  Open& node = open_.back();
  if (format_ == Format::binary) out_.push_back(type);
  else out_ += node.props == 0 ? " " : ", ";
  ++node.props;
}

FbxEncoder& FbxEncoder::i32(std::int32_t v) {
  before_prop('I');
  if (format_ == Format::binary) put_le(out_, static_cast<std::uint32_t>(v));
  else out_ += std::to_string(v);
  return *this;
}

FbxEncoder& FbxEncoder::i64(std::int64_t v) {
  before_prop('L');
  if (format_ == Format::binary) put_le(out_, static_cast<std::uint64_t>(v));
  else out_ += std::to_string(v);
  return *this;
}

FbxEncoder& FbxEncoder::f64(double v) {
  before_prop('D');
  if (format_ == Format::binary) put_le(out_, bits(v));
  else put_number_text(out_, v);
  return *this;
}

FbxEncoder& FbxEncoder::str(std::string_view s) {
  before_prop('S');
  if (format_ == Format::binary) put_sized(out_, s);
  else out_ += quoted(s);
  return *this;
}

FbxEncoder& FbxEncoder::raw(std::string_view bytes) {
  before_prop('R');
  if (format_ == Format::binary) {
    put_sized(out_, bytes);
  } else {
    // ASCII FBX spells raw bytes in base64.
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
      std::uint32_t v = static_cast<unsigned char>(bytes[i]) << 16;
      if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
      if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
      for (std::size_t k = 0; k < 4; ++k) b64 += i + k <= bytes.size() ? digits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    out_ += quoted(b64);
  }
  return *this;
}

template <class T>
void FbxEncoder::array(char type, const std::vector<T>& a) {
  before_prop(type);
  if (format_ == Format::ascii) {
    Open& node = open_.back();
    out_ += "*" + std::to_string(a.size()) + " {\n";
    out_.append(open_.size(), '\t');
    out_ += "a: ";
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i) out_ += (i % 16 == 0) ? ",\n" + std::string(open_.size(), '\t') : ",";
      put_number_text(out_, a[i]);
    }
    out_ += "\n";
    node.children = true;  // end() closes the array's braces: nothing may follow it
    return;
  }
  std::string bytes;
  bytes.reserve(a.size() * sizeof(T));
  for (const T& v : a) {
    if constexpr (std::is_floating_point_v<T>) put_le(bytes, bits(v));
    else put_le(bytes, static_cast<std::make_unsigned_t<T>>(v));
  }
  std::uint32_t encoding = 0;
  if (bytes.size() > kCompressAbove) {
    uLongf len = compressBound(static_cast<uLong>(bytes.size()));
    std::string packed(len, '\0');
    if (compress2(reinterpret_cast<Bytef*>(packed.data()), &len, reinterpret_cast<const Bytef*>(bytes.data()),
                  static_cast<uLong>(bytes.size()), 1) == Z_OK) {
      packed.resize(len);
      bytes.swap(packed);
      encoding = 1;
    }
  }
  if (a.size() > std::numeric_limits<std::uint32_t>::max() || bytes.size() > std::numeric_limits<std::uint32_t>::max())
    too_large_ = true;
  put_le(out_, static_cast<std::uint32_t>(a.size()));
  put_le(out_, encoding);
  put_le(out_, static_cast<std::uint32_t>(bytes.size()));
  out_ += bytes;
}

FbxEncoder& FbxEncoder::property(const FbxProperty& p) {
  switch (p.type) {
    case 'C':
    case 'Y':
      before_prop(p.type);
      // A bool byte as stored: 0/1, or Maya's 'Y'/'T' (Shading), which ASCII spells as the letter.
      if (format_ == Format::ascii && p.type == 'C' && std::isupper(static_cast<int>(p.integer))) out_.push_back(static_cast<char>(p.integer));
      else if (format_ == Format::ascii) out_ += std::to_string(p.integer);
      else if (p.type == 'C') out_.push_back(static_cast<char>(p.integer));
      else put_le(out_, static_cast<std::uint16_t>(p.integer));
      return *this;
    case 'I': return i32(static_cast<std::int32_t>(p.integer));
    case 'L': return i64(p.integer);
    case 'F':
      before_prop('F');
      if (format_ == Format::ascii) put_number_text(out_, static_cast<float>(p.number));
      else put_le(out_, bits(static_cast<float>(p.number)));
      return *this;
    case 'D': return f64(p.number);
    case 'S': return str(p.text);
    case 'R': return raw(p.text);
    case 'b': {
      std::vector<std::int8_t> flags(p.integers.begin(), p.integers.end());
      array('b', flags);
      return *this;
    }
    case 'i': return i32_array(std::vector<std::int32_t>(p.integers.begin(), p.integers.end()));
    case 'l': return i64_array(p.integers);
    case 'f': return f32_array(std::vector<float>(p.numbers.begin(), p.numbers.end()));
    default: return f64_array(p.numbers);  // 'd'
  }
}

void FbxEncoder::node(const FbxNode& n) {
  begin(n.name);
  for (const FbxProperty& p : n.properties) property(p);
  for (const FbxNode& child : n.children) node(child);
  end();
}

FbxEncoder& FbxEncoder::i32_array(const std::vector<std::int32_t>& a) { array('i', a); return *this; }
FbxEncoder& FbxEncoder::i64_array(const std::vector<std::int64_t>& a) { array('l', a); return *this; }
FbxEncoder& FbxEncoder::f32_array(const std::vector<float>& a) { array('f', a); return *this; }
FbxEncoder& FbxEncoder::f64_array(const std::vector<double>& a) { array('d', a); return *this; }

Result<std::string> FbxEncoder::finish() {
  ROTINTERP_ASSERT(open_.empty());
  if (format_ == Format::ascii) return std::move(out_);
  out_.append(kNullRecord, '\0');
  out_.append(reinterpret_cast<const char*>(kFooterId), sizeof kFooterId);
  out_.append(4, '\0');
  // Zero padding to a 16-byte boundary (a full 16 when already aligned).
  const std::size_t pad = 16 - out_.size() % 16;
  out_.append(pad, '\0');
  put_le<std::uint32_t>(out_, kVersion);
  out_.append(120, '\0');
  out_.append(reinterpret_cast<const char*>(kFooterMagic), sizeof kFooterMagic);
  if (too_large_) return make_error("the binary FBX would pass 4 GiB (32-bit offsets); write .gltf/.glb or fewer frames");
  return std::move(out_);
}

}  // namespace rotinterp
