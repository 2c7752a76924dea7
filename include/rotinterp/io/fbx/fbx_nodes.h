// The FBX node tree as stored, read from binary FBX (versions 6.1 through 7.7) or
// ASCII FBX: our own reader, independent of assimp, for what assimp does not keep
// (animation curves with their tangents, FBX 6.1 takes).
//
// An FBX document is a list of nodes; a node has a name, typed properties and
// child nodes. Binary layout (little-endian; Blender's public "FBX binary file
// format specification"): a 27-byte header ("Kaydara FBX Binary  \0\x1a\0", uint32
// version), then node records: end offset, property count, property bytes (uint32
// each before 7.5, uint64 from 7.5), uint8 name length, name, properties,
// children, closed by a null record (13 or 25 zero bytes). Arrays may be zlib
// streams. ASCII: `Name: prop, prop {` children `}`, arrays as `*N { a: … }`.
//
// Rules the reader enforces (each refusal is one line naming the file and the
// node path, e.g. "clip.fbx: FBX node Objects/AnimationCurve/KeyTime: …"):
//  1. nothing is read past the buffer; every offset and length is checked first;
//  2. nesting deeper than kFbxMaxDepth is refused (bounded recursion);
//  3. an array's element count must fit in the bytes that hold it (raw arrays
//     exactly; zlib arrays within zlib's largest ratio) and in kFbxMaxArrayElements;
//  4. a zlib array must inflate to exactly its declared size.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/files/limits.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// One property. Binary type codes are kept: 'C' bool, 'Y' int16, 'I' int32,
// 'L' int64 (all in `integer`), 'F' float, 'D' double (`number`), 'S' string,
// 'R' raw bytes (`text`), arrays 'b' 'i' 'l' (`integers`) and 'f' 'd' (`numbers`).
// ASCII gives 'L' for integers, 'D' for other numbers, 'S' for quoted strings and
// bare words, 'l' or 'd' for arrays (integer literals only, or not).
struct FbxProperty {
  char type = 'L';
  std::int64_t integer = 0;
  double number = 0.0;
  std::string text;
  std::vector<std::int64_t> integers;
  std::vector<double> numbers;

  bool is_integer() const { return type == 'C' || type == 'Y' || type == 'I' || type == 'L'; }
  bool is_number() const { return is_integer() || type == 'F' || type == 'D'; }
  bool is_string() const { return type == 'S' || type == 'R'; }
  bool is_array() const { return type == 'b' || type == 'i' || type == 'l' || type == 'f' || type == 'd'; }
  // A scalar number as a double (0 for strings and arrays).
  double as_double() const { return is_integer() ? static_cast<double>(integer) : number; }
  // An array's (or a number's) values as doubles.
  std::vector<double> as_doubles() const;
};

struct FbxNode {
  std::string name;
  std::vector<FbxProperty> properties;
  std::vector<FbxNode> children;

  // The first child with this name, or nullptr.
  const FbxNode* child(std::string_view child_name) const;
};

struct FbxDocument {
  bool binary = false;
  std::uint32_t version = 0;  // 6100, 7400, 7500, … (ASCII: from the "; FBX 7.5.0" line or FBXVersion)
  std::vector<FbxNode> nodes;

  const FbxNode* node(std::string_view name) const;
};

// A name from the file as an error message may show it: control characters as
// '?', at most 200 bytes (messages are one line).
std::string fbx_printable(std::string_view name);

// "file.fbx: FBX node Objects/AnimationCurve/KeyTime" for the node names `path` (from
// the top): what the readers' errors start with.
std::string fbx_node_where(const std::string& label, const std::vector<std::string>& path);

// Whether `bytes` start with the binary FBX magic.
bool is_binary_fbx(std::string_view bytes);

// Reads a whole FBX file's bytes (binary or ASCII, chosen by the magic). `label`
// names the file in errors (file_error::unreadable).
Result<FbxDocument> parse_fbx_nodes(std::string_view bytes, const std::string& label);

// The file at `path` (io/files/input_file.h read_input_file) through parse_fbx_nodes.
Result<FbxDocument> read_fbx_file(const std::string& path, const std::string& label);

// The two encodings, for the tests (parse_fbx_nodes chooses).
Result<FbxDocument> parse_fbx_binary(std::string_view bytes, const std::string& label);
Result<FbxDocument> parse_fbx_ascii(std::string_view bytes, const std::string& label);

}  // namespace rotinterp
