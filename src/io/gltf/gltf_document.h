// The parts our glTF writers share (private to src/io/gltf): the binary buffer with
// its buffer views and accessors, the animation of a clip, and the file written
// from a finished document. gltf_write.cpp writes a skeleton of our own with them,
// gltf_character.cpp a source's document with its animations replaced.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/gltf/gltf_write.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp::gltf {

constexpr int kFloat = 5126;  // glTF componentType FLOAT

void put_float(std::string& out, double v);

// The buffer (buffer 0) and the accessors into it: one buffer view per accessor.
// Every view starts on a 4-byte boundary (the spec's alignment for every component
// type): a builder that starts from bytes of another's keeps `bin` padded.
struct Builder {
  std::string bin;
  nlohmann::json views = nlohmann::json::array();
  nlohmann::json accessors = nlohmann::json::array();

  // Floats already appended from `start`; `count` elements of `type` ("VEC4", …).
  int accessor(std::size_t start, std::size_t count, const char* type, nlohmann::json extra = nlohmann::json::object());
};

// Where each joint's channels go: its node (kNone: the joint gets no channel), and
// its translations' factor from clip units to the file's numbers (metres, divided by
// any scale of its ancestors).
struct JointTargets {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> node;
  std::vector<double> translation_scale;
};

// One animation of `clip`: per joint its rotation sampler (and translation sampler
// where it has a translation track), their accessors appended to `b` in joint order
// (GltfKeys as in gltf_write.h).
Result<nlohmann::json> animation(Builder& b, const Clip& clip, const GltfKeys& keys, const JointTargets& targets);

// Writes `doc` (one buffer, `bin`) to `path` as .glb, or as .gltf with its buffer
// beside it (gltf_write.h): atomically, the 4 GiB limit of a GLB checked.
Status write_document(nlohmann::json doc, std::string bin, const std::filesystem::path& path, bool binary);

}  // namespace rotinterp::gltf
