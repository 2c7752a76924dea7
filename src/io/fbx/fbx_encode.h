// The FBX node tree, written as it is produced: binary FBX 7.4 or ASCII FBX 7.4
// (private to src/io).
//
// An FBX document is a list of nodes; a node has a name, a list of typed
// properties and child nodes. Binary layout (FBX 7.4, little-endian, as described
// in the public format notes — Blender's "FBX binary file format specification"):
//   header  "Kaydara FBX Binary  \0", 0x1A, 0x00, uint32 version
//   node    uint32 end offset (absolute), uint32 property count, uint32 property
//           bytes, uint8 name length, name, properties, children, and a 13-byte null
//           record after the children (also after a node without properties)
//   top     the nodes, then a null record, then the footer
// Arrays are zlib-compressed when larger than 128 bytes (as the FBX SDK does).
// Offsets are 32-bit: a binary file is limited to 4 GiB (finish() says so).
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

class FbxEncoder {
 public:
  enum class Format { binary, ascii };
  static constexpr std::uint32_t kVersion = 7400;

  explicit FbxEncoder(Format format);

  Format format() const { return format_; }
  // Opens a node (a child of the open one, or a top-level node); its properties
  // follow, then its children, then end().
  void begin(std::string_view name);
  void end();

  // Properties of the open node (before its first child).
  FbxEncoder& i32(std::int32_t v);     // 'I'
  FbxEncoder& i64(std::int64_t v);     // 'L'
  FbxEncoder& f64(double v);           // 'D'
  FbxEncoder& str(std::string_view s); // 'S'
  FbxEncoder& raw(std::string_view bytes);  // 'R'
  FbxEncoder& i32_array(const std::vector<std::int32_t>& a);  // 'i'
  FbxEncoder& i64_array(const std::vector<std::int64_t>& a);  // 'l'
  FbxEncoder& f32_array(const std::vector<float>& a);         // 'f'
  FbxEncoder& f64_array(const std::vector<double>& a);        // 'd'
  // A property as read (io/fbx/fbx_nodes.h), in its own type: what a tree edit
  // writes back unchanged. ASCII spells bools and int16s as integers.
  FbxEncoder& property(const FbxProperty& p);
  // A read node with its properties and children, unchanged.
  void node(const FbxNode& n);

  // An object's name with its class as each encoding spells it: "Hips\0\1Model"
  // in binary, "Model::Hips" in ASCII.
  std::string object_name(std::string_view name, std::string_view cls) const;

  // The whole file: header, nodes, footer. Every node must be closed. Error when
  // a binary file would pass 4 GiB (32-bit offsets).
  Result<std::string> finish();

 private:
  struct Open {
    std::size_t header = 0;       // binary: offset of the node's record
    std::size_t props_start = 0;  // binary: offset of the first property
    std::uint32_t props = 0;
    bool children = false;
    bool always_block = false;    // ASCII/binary: write a block even without children
  };
  void close_props(Open& node);
  void before_prop(char type);
  template <class T>
  void array(char type, const std::vector<T>& a);

  Format format_;
  std::string out_;
  std::vector<Open> open_;
  bool too_large_ = false;
};

}  // namespace rotinterp
