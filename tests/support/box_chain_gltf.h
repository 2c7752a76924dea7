// A glTF file of `boxes` rigid boxes whose nodes all sit at one point: joint k
// (animated, at the origin) parents joint k+1 and a mesh node (at the origin too)
// whose box is centred at (k + 1, 0, 0) in its own frame — each box hangs off its
// pivot, as exported props and rigid parts often do. A viewer shows a row of boxes.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rotinterp::test {

inline void write_box_chain_gltf(const std::filesystem::path& gltf, int boxes) {
  std::vector<std::uint8_t> bin;
  auto put_floats = [&](std::initializer_list<float> values) {
    for (float v : values) {
      std::uint8_t b[4];
      std::memcpy(b, &v, 4);
      bin.insert(bin.end(), b, b + 4);
    }
  };
  // Indices of a box's 12 triangles (36 × uint16), then times, rotations, vertices.
  static const std::uint16_t kTriangles[36] = {0, 1, 2, 2, 1, 3, 4, 6, 5, 5, 6, 7, 0, 4, 1, 1, 4, 5,
                                               2, 3, 6, 6, 3, 7, 0, 2, 4, 4, 2, 6, 1, 5, 3, 3, 5, 7};
  for (std::uint16_t i : kTriangles) bin.insert(bin.end(), {static_cast<std::uint8_t>(i & 0xff), static_cast<std::uint8_t>(i >> 8)});
  put_floats({0.0f, 1.0f});                                         // times: offset 72
  put_floats({0, 0, 0, 1, 0, 0, 0.0871557f, 0.9961947f});           // identity, 10° about z: offset 80
  const std::size_t vertices = bin.size();                          // 112
  for (int k = 0; k < boxes; ++k) {
    const float cx = static_cast<float>(k + 1);
    for (int v = 0; v < 8; ++v)
      put_floats({cx + ((v & 1) ? 0.4f : -0.4f), (v & 2) ? 0.4f : -0.4f, (v & 4) ? 0.4f : -0.4f});
  }
  const std::filesystem::path bin_path = gltf.parent_path() / (gltf.stem().string() + ".bin");
  std::ofstream(bin_path, std::ios::binary).write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));

  std::string nodes, meshes, accessors, samplers, channels;
  accessors += R"({"bufferView":0,"componentType":5123,"count":36,"type":"SCALAR"},)";
  accessors += R"({"bufferView":1,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[1]},)";
  accessors += R"({"bufferView":2,"componentType":5126,"count":2,"type":"VEC4"})";
  for (int k = 0; k < boxes; ++k) {
    const std::string joint = std::to_string(2 * k), box = std::to_string(2 * k + 1), ks = std::to_string(k);
    const std::string children = k + 1 < boxes ? "[" + box + "," + std::to_string(2 * k + 2) + "]" : "[" + box + "]";
    nodes += std::string(k ? "," : "") + R"({"name":"J)" + ks + R"(","children":)" + children + R"(},{"name":"Box)" + ks +
             R"(","mesh":)" + ks + "}";
    meshes += std::string(k ? "," : "") + R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(3 + k) +
              R"(},"indices":0}]})";
    const float cx = static_cast<float>(k + 1);
    accessors += R"(,{"bufferView":3,"byteOffset":)" + std::to_string(k * 96) +
                 R"(,"componentType":5126,"count":8,"type":"VEC3","min":[)" + std::to_string(cx - 0.4f) + ",-0.4,-0.4],\"max\":[" +
                 std::to_string(cx + 0.4f) + ",0.4,0.4]}";
    samplers += std::string(k ? "," : "") + R"({"input":1,"output":2,"interpolation":"LINEAR"})";
    channels += std::string(k ? "," : "") + R"({"sampler":)" + ks + R"(,"target":{"node":)" + joint + R"(,"path":"rotation"}})";
  }
  std::ofstream(gltf) << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[)" << nodes
                      << R"(],"meshes":[)" << meshes << R"(],"buffers":[{"uri":")" << bin_path.filename().string()
                      << R"(","byteLength":)" << bin.size() << R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":72},)"
                      << R"({"buffer":0,"byteOffset":72,"byteLength":8},{"buffer":0,"byteOffset":80,"byteLength":32},)"
                      << R"({"buffer":0,"byteOffset":)" << vertices << R"(,"byteLength":)" << bin.size() - vertices
                      << R"(}],"accessors":[)" << accessors << R"(],"animations":[{"samplers":[)" << samplers
                      << R"(],"channels":[)" << channels << "]}]}";
}

}  // namespace rotinterp::test
