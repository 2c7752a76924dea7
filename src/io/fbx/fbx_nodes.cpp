// The FBX node tree's accessors and the choice between the binary and ASCII readers.
#include "rotinterp/io/fbx/fbx_nodes.h"

#include "rotinterp/io/files/input_file.h"

#include <cstring>

namespace rotinterp {

namespace {
constexpr char kBinaryMagic[] = "Kaydara FBX Binary  ";  // 20 characters, then \0
}

std::vector<double> FbxProperty::as_doubles() const {
  if (!integers.empty()) return std::vector<double>(integers.begin(), integers.end());
  if (!numbers.empty() || is_array()) return numbers;
  if (is_number()) return {as_double()};
  return {};
}

const FbxNode* FbxNode::child(std::string_view child_name) const {
  for (const FbxNode& c : children)
    if (c.name == child_name) return &c;
  return nullptr;
}

const FbxNode* FbxDocument::node(std::string_view name) const {
  for (const FbxNode& n : nodes)
    if (n.name == name) return &n;
  return nullptr;
}

std::string fbx_printable(std::string_view name) {
  constexpr std::size_t kMaxShown = 200;
  std::string out(name.substr(0, kMaxShown));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (name.size() > kMaxShown) out += "…";
  return out;
}

std::string fbx_node_where(const std::string& label, const std::vector<std::string>& path) {
  std::string where;
  for (const std::string& n : path) where += (where.empty() ? "" : "/") + fbx_printable(n);
  return label + ": FBX node " + (where.empty() ? "(top level)" : where);
}

bool is_binary_fbx(std::string_view bytes) {
  return bytes.size() >= 21 && std::memcmp(bytes.data(), kBinaryMagic, 21) == 0;
}

Result<FbxDocument> parse_fbx_nodes(std::string_view bytes, const std::string& label) {
  return is_binary_fbx(bytes) ? parse_fbx_binary(bytes, label) : parse_fbx_ascii(bytes, label);
}

Result<FbxDocument> read_fbx_file(const std::string& path, const std::string& label) {
  Result<std::string> bytes = read_input_file(path, label);
  if (!bytes) return bytes.failure();
  return parse_fbx_nodes(*bytes, label);
}

}  // namespace rotinterp
