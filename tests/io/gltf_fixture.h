// A small glTF file built in the test, bytes and all: three nodes under a root, each
// animated by one kind of sampler, keys at non-uniform times from a non-zero time.
//   Linear:  rotation LINEAR, a step over 90° and a stored sign flip between keys;
//            translation LINEAR;
//   Cubic:   rotation CUBICSPLINE with non-zero tangents;
//   Stepped: rotation STEP and translation STEP, at different key times.
// The key values are stored as float; `keys` holds them as the file does (rounded to
// float), so that an evaluation in double from them is exact.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace rotinterp::test {

struct FixtureSampler {
  std::string node, path, interpolation;  // as in the file: "rotation", "LINEAR", …
  std::vector<double> times;              // float-rounded
  std::vector<double> values;             // float-rounded, width (4 or 3) per element
};

inline double to_float(double v) { return static_cast<double>(static_cast<float>(v)); }

inline std::vector<double> quat_xyzw(double angle, double x, double y, double z, double sign = 1.0) {
  const double n = std::sqrt(x * x + y * y + z * z), s = std::sin(angle / 2) / n;
  return {sign * x * s, sign * y * s, sign * z * s, sign * std::cos(angle / 2)};
}

inline std::vector<FixtureSampler> fixture_samplers() {
  auto join = [](std::initializer_list<std::vector<double>> parts) {
    std::vector<double> out;
    for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
    for (double& v : out) v = to_float(v);
    return out;
  };
  auto times = [](std::vector<double> t) {
    for (double& v : t) v = to_float(v);
    return t;
  };
  std::vector<FixtureSampler> out;
  // 0.2 rad, then 2.2 rad about another axis (a step of ~126°), then the same
  // orientation's negative neighbour (dot < 0 as stored), then a small step.
  out.push_back({"Linear", "rotation", "LINEAR", times({0.25, 0.4, 0.9, 1.0, 1.75}),
                 join({quat_xyzw(0.2, 0, 0, 1), quat_xyzw(2.2, 1, 0, 0.3), quat_xyzw(2.6, 1, 0.2, 0.3, -1.0),
                       quat_xyzw(2.7, 1, 0.25, 0.3, -1.0), quat_xyzw(2.75, 0.9, 0.25, 0.3)})});
  out.push_back({"Linear", "translation", "LINEAR", times({0.3, 1.2}), join({{0, 1, 0}, {0.5, 1.5, -0.25}})});
  // in-tangent, value, out-tangent per key (tangents in value per second).
  out.push_back({"Cubic", "rotation", "CUBICSPLINE", times({0.3, 0.5, 1.1, 1.6}),
                 join({{0.1, 0.2, 0, 0}, quat_xyzw(0.3, 0, 1, 0), {0.4, -0.3, 0.2, 0.1},
                       {0.0, 0.5, 0.1, -0.2}, quat_xyzw(1.2, 0.2, 1, 0), {0.6, 0.1, -0.4, 0.3},
                       {-0.2, 0.3, 0.3, 0.1}, quat_xyzw(1.9, 0.5, 1, 0.1), {0.2, 0.2, 0.2, -0.5},
                       {0.3, -0.1, 0.0, 0.2}, quat_xyzw(2.4, 0.5, 0.8, 0.4), {0.1, 0.1, 0.1, 0.1}})});
  out.push_back({"Stepped", "rotation", "STEP", times({0.2, 0.7, 1.3}),
                 join({quat_xyzw(0.5, 0, 0, 1), quat_xyzw(1.5, 0, 1, 1), quat_xyzw(0.1, 1, 1, 0)})});
  out.push_back({"Stepped", "translation", "STEP", times({0.2, 0.6, 1.5}), join({{1, 0, 0}, {1, 0.5, 0}, {2, 0.5, 0}})});
  return out;
}

// The file: ".glb" (JSON and BIN chunks) when `glb`, else ".gltf" JSON with one data:
// URI buffer. `buffer_uri`, when given, replaces the buffer's uri (refusal tests).
inline std::string fixture_file(bool glb, const std::string& buffer_uri = "") {
  using nlohmann::json;
  const std::vector<FixtureSampler> samplers = fixture_samplers();
  std::string bin;
  json accessors = json::array(), views = json::array();
  auto add = [&](const std::vector<double>& numbers, const char* type, std::size_t width) {
    views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", numbers.size() * 4}});
    for (double v : numbers) {
      const float f = static_cast<float>(v);
      char b[4];
      std::memcpy(b, &f, 4);  // little-endian hosts only, as the tests run
      bin.append(b, 4);
    }
    accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", 5126}, {"count", numbers.size() / width},
                         {"type", type}});
    return accessors.size() - 1;
  };
  const std::vector<std::string> names = {"Root", "Linear", "Cubic", "Stepped"};
  json nodes = json::array({{{"name", "Root"}, {"children", {1, 2, 3}}, {"translation", {0, 1, 0}}}});
  for (std::size_t i = 1; i < names.size(); ++i)
    nodes.push_back({{"name", names[i]}, {"translation", {0.1 * static_cast<double>(i), 1, 0}}});
  json anim_samplers = json::array(), channels = json::array();
  for (const FixtureSampler& s : samplers) {
    const std::size_t width = s.path == "rotation" ? 4 : 3;
    const auto input = add(s.times, "SCALAR", 1);
    const auto output = add(s.values, width == 4 ? "VEC4" : "VEC3", width);
    anim_samplers.push_back({{"input", input}, {"output", output}, {"interpolation", s.interpolation}});
    const auto node = static_cast<std::size_t>(std::find(names.begin(), names.end(), s.node) - names.begin());
    channels.push_back({{"sampler", anim_samplers.size() - 1}, {"target", {{"node", node}, {"path", s.path}}}});
  }
  json doc = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              {"nodes", nodes},
              {"accessors", accessors},
              {"bufferViews", views},
              {"animations", {{{"name", "Fixture"}, {"samplers", anim_samplers}, {"channels", channels}}}}};
  json buffer = {{"byteLength", bin.size()}};
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  if (!buffer_uri.empty()) {
    buffer["uri"] = buffer_uri;
  } else if (!glb) {
    std::string text;
    for (std::size_t i = 0; i < bin.size(); i += 3) {
      std::uint32_t v = static_cast<unsigned char>(bin[i]) << 16;
      if (i + 1 < bin.size()) v |= static_cast<unsigned char>(bin[i + 1]) << 8;
      if (i + 2 < bin.size()) v |= static_cast<unsigned char>(bin[i + 2]);
      for (std::size_t k = 0; k < 4; ++k)
        text.push_back(i + k <= bin.size() ? kAlphabet[(v >> (18 - 6 * k)) & 63] : '=');
    }
    buffer["uri"] = "data:application/octet-stream;base64," + text;
  }
  doc["buffers"] = json::array({buffer});
  std::string text = doc.dump();
  if (!glb) return text;
  while (text.size() % 4) text.push_back(' ');
  while (bin.size() % 4) bin.push_back('\0');
  std::string out;
  auto u32 = [&out](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  u32(0x46546C67);
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  u32(static_cast<std::uint32_t>(text.size()));
  u32(0x4E4F534A);
  out += text;
  u32(static_cast<std::uint32_t>(bin.size()));
  u32(0x004E4942);
  out += bin;
  return out;
}

}  // namespace rotinterp::test
