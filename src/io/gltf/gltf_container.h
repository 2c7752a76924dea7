// The glTF 2.0 file as stored (private to src/io/gltf): a GLB's chunks or a
// .gltf's JSON, and its buffers, each read when first asked for. Shared by the
// animation reader (gltf_read.cpp) and the character edit (gltf_character.cpp).
// Every number taken from the file is checked before it indexes anything: errors
// throw std::runtime_error, which each entry point turns into one line.
#pragma once

#include "rotinterp/core/result.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp::gltf {

using nlohmann::json;

struct Container {
  std::string_view json;
  std::optional<std::string_view> bin;  // GLB: its BIN chunk (buffer 0 without a uri)
};

// A GLB's JSON and BIN chunks, or `bytes` as a .gltf's JSON (no GLB magic).
Result<Container> split_container(std::string_view bytes, const std::string& label);

// A URI's %XX escapes decoded (glTF URIs are RFC 3986 references).
std::string percent_decoded(const std::string& uri);

// A whole number >= 0 that the spec requires (indices, offsets, lengths, counts);
// `fallback` where the key is missing, else an error.
std::uint64_t whole(const json& object, const char* key, std::optional<std::uint64_t> fallback = std::nullopt);

// doc[array][index], or an error where there is none.
const json& element(const json& doc, const char* array, std::uint64_t index);

// Each node's name as assimp names it (its "name", else "nodes_<index>", assimp's
// GetNodeName), which a clip's joints carry (io/gltf/gltf_source.h).
std::vector<std::string> node_names(const json& doc);

// The file's buffers, read when first used: the GLB's BIN chunk, a base64 data: URI,
// or a file beside the .gltf (io/files/input_file.h referenced_file; others only with
// allow_external_files), each cut to its byteLength.
class Buffers {
 public:
  Buffers(const json& doc, const Container& file, std::filesystem::path folder, bool allow_external_files)
      : doc_(doc), file_(file), folder_(std::move(folder)), allow_external_files_(allow_external_files) {}

  std::string_view bytes(std::uint64_t index);

 private:
  std::string load(std::uint64_t index);

  const json& doc_;
  const Container& file_;
  std::filesystem::path folder_;
  bool allow_external_files_;
  std::map<std::uint64_t, std::string> loaded_;
};

}  // namespace rotinterp::gltf
