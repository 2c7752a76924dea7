// The glTF character edit: the source's document with its animations replaced by
// the takes (io/gltf/gltf_character.h).
#include "rotinterp/io/gltf/gltf_character.h"

#include "gltf_container.h"
#include "gltf_document.h"
#include "gltf_repack.h"
#include "rotinterp/io/files/input_file.h"
#include "rotinterp/io/files/kept_text.h"
#include "rotinterp/io/gltf/gltf_source.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <cstring>
#include <stdexcept>

namespace rotinterp {

namespace {

using namespace gltf;

// A node scale within this of 1 is no scale, as the reader takes it (io/import/scene_to_clip.cpp).
constexpr double kUnitScaleTolerance = 1e-5;
// Values of a channel within this (relative to max(1, |value|)) hold still: float round-off.
constexpr double kStill = 1e-5;
// A rotation key at most this from the rest rotation (sine of half the angle between
// them: 2e-6 rad) is at rest; float round-off of stored keys is ~1e-7.
constexpr double kAtRest = 1e-6;

// The uniform scale the reader baked into a node's children's translations: the cube
// root of its static scale's volume; 1 for none, a non-positive or a near-1 one.
double baked_scale(const json& node) {
  if (!node.contains("scale")) return 1.0;
  const json& s = node["scale"];
  const double x = s.at(0).get<double>(), y = s.at(1).get<double>(), z = s.at(2).get<double>();
  if (std::min({x, y, z}) <= 0.0) return 1.0;
  const double scale = std::cbrt(x * y * z);
  return std::isfinite(scale) && std::abs(scale - 1.0) >= kUnitScaleTolerance ? scale : 1.0;
}

// Per node: the product of its ancestors' baked scales.
std::vector<double> ancestor_scales(const json& doc) {
  const std::size_t n = doc.contains("nodes") ? doc["nodes"].size() : 0;
  std::vector<int> parent(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    for (const json& c : doc["nodes"][i].value("children", json::array()))
      if (const std::uint64_t child = c.get<std::uint64_t>(); child < n) parent[child] = static_cast<int>(i);
  std::vector<double> out(n, 1.0);
  for (std::size_t i = 0; i < n; ++i)
    for (int p = parent[i], steps = 0; p >= 0 && steps < static_cast<int>(n); p = parent[static_cast<std::size_t>(p)], ++steps)
      out[i] *= baked_scale(doc["nodes"][static_cast<std::size_t>(p)]);
  return out;
}

// Whether joint j of `clip` leaves its rest: a translation track (the reader makes
// one only where it moves), or a rotation key off the rest rotation.
bool leaves_rest(const Clip& clip, std::size_t j) {
  if (clip.translations[j]) return true;
  const Quat& rest = clip.skeleton.joints[j].rest_rotation;
  for (const Quat& q : clip.rotations[j].keys)
    if ((rest.conjugate() * q).vec().norm() > kAtRest) return true;
  return false;
}

// The nodes the source's animation named `name` targets (none where it has no such animation).
std::set<std::size_t> nodes_animated_by(const json& doc, const std::string& name) {
  std::set<std::size_t> out;
  for (const json& animation : doc.value("animations", json::array()))
    if (animation.value("name", std::string()) == name)
      for (const json& channel : animation.value("channels", json::array()))
        if (channel.at("target").contains("node")) out.insert(whole(channel.at("target"), "node"));
  return out;
}

// Where each joint's channels go; errors name the joint that has no node of its own.
// A joint gets channels where the source's animation of the take's name animates
// its node or where it leaves its rest, so that a take keeps the source's channels
// (and readers the source's actions); every joint where that leaves none.
JointTargets joint_targets(const json& doc, const Clip& clip) {
  const std::vector<int> node = gltf_node_of_joints(clip.skeleton, node_names(doc));
  const std::vector<double> scales = ancestor_scales(doc);
  JointTargets out;
  for (std::size_t j = 0; j < node.size(); ++j) {
    const std::string& name = clip.skeleton.joints[j].name;
    if (node[j] < 0) throw std::runtime_error("joint '" + name + "' has no node of its name, or several");
    const std::size_t n = static_cast<std::size_t>(node[j]);
    if (doc["nodes"][n].contains("matrix"))
      throw std::runtime_error("joint '" + name + "' is a node stored as a matrix, which no animation may target");
    out.node.push_back(n);
    out.translation_scale.push_back(metres_per_unit(clip) / scales[n]);
  }
  const std::set<std::size_t> animated = nodes_animated_by(doc, clip.name);
  std::vector<std::size_t> written = out.node;
  for (std::size_t j = 0; j < written.size(); ++j)
    if (!animated.count(written[j]) && !leaves_rest(clip, j)) written[j] = JointTargets::kNone;
  if (std::any_of(written.begin(), written.end(), [](std::size_t n) { return n != JointTargets::kNone; })) out.node = written;
  return out;
}

float float_at(std::string_view bytes, std::size_t at) {
  std::uint32_t u = 0;
  for (int i = 3; i >= 0; --i) u = (u << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

// Whether the float accessor `index` holds more than one value (a sampler output);
// any other component type is taken as moving.
bool moves(const json& doc, Buffers& buffers, std::uint64_t index) {
  const json& accessor = element(doc, "accessors", index);
  if (accessor.value("componentType", 0) != kFloat || !accessor.contains("bufferView") || accessor.contains("sparse"))
    return accessor.contains("bufferView") || accessor.contains("sparse");
  const json& view = element(doc, "bufferViews", whole(accessor, "bufferView"));
  const std::string_view buffer = buffers.bytes(whole(view, "buffer"));
  const std::uint64_t width = std::string(accessor.value("type", "SCALAR")) == "VEC3" ? 3 : 1;
  const std::uint64_t stride = whole(view, "byteStride", 4 * width), count = whole(accessor, "count");
  const std::uint64_t start = whole(view, "byteOffset", 0) + whole(accessor, "byteOffset", 0);
  if (count == 0) return false;
  if (start + stride * (count - 1) + 4 * width > buffer.size()) throw std::runtime_error("accessor " + std::to_string(index) + " passes its buffer");
  for (std::uint64_t e = 1; e < count; ++e)
    for (std::uint64_t c = 0; c < width; ++c) {
      const double first = float_at(buffer, start + 4 * c), v = float_at(buffer, start + e * stride + 4 * c);
      if (std::abs(v - first) > kStill * std::max(1.0, std::abs(first))) return true;
    }
  return false;
}

// The source's channels we do not write (scale, morph weights) whose values move.
std::size_t moving_other_channels(const json& doc, Buffers& buffers) {
  std::size_t n = 0;
  for (const json& animation : doc.value("animations", json::array()))
    for (const json& channel : animation.value("channels", json::array())) {
      const std::string path = channel.at("target").value("path", std::string());
      if (path == "rotation" || path == "translation") continue;
      const json& sampler = animation.at("samplers").at(whole(channel, "sampler"));
      if (moves(doc, buffers, whole(sampler, "output"))) ++n;
    }
  return n;
}

std::size_t count_of(const json& doc, const char* array) { return doc.contains(array) ? doc[array].size() : 0; }

}  // namespace

std::string GltfKept::text() const {
  std::vector<std::string> parts;
  if (meshes) parts.push_back(count_text(meshes, "mesh", "meshes"));
  if (skins) parts.push_back(count_text(skins, "skin", "skins") + " (" + count_text(joints, "joint", "joints") + ")");
  if (materials) parts.push_back(count_text(materials, "material", "materials"));
  if (textures) parts.push_back(count_text(textures, "texture", "textures"));
  if (images) parts.push_back(count_text(images, "image", "images"));
  if (cameras) parts.push_back(count_text(cameras, "camera", "cameras"));
  std::string s = kept_text(parts);
  if (embedded_images) s += "; " + count_text(embedded_images, "image", "images") + " embedded from files beside the source";
  if (dropped_channels)
    s += "; dropped: " + count_text(dropped_channels, "animated scale or morph-weight channel", "animated scale or morph-weight channels");
  return s;
}

// The source's declaration of an extension only its animations used (they are
// replaced, ours use none): dropped, so that no reader is told of an extension the
// file no longer uses.
void undeclare_animation_extensions(json& doc) {
  for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
    if (!doc.contains(list) || !doc[list].is_array()) continue;
    json& names = doc[list];
    names.erase(std::remove(names.begin(), names.end(), json("KHR_animation_pointer")), names.end());
    if (names.empty()) doc.erase(list);
  }
}

Result<GltfKept> write_gltf_character(const std::vector<const Clip*>& takes, const std::filesystem::path& source,
                                      const std::filesystem::path& path, bool binary, const GltfKeys& keys) {
  const std::string label = source.string();
  if (takes.empty()) return make_error(path.string() + ": no takes to write");
  auto bytes = read_input_file(source, label);
  if (!bytes) return bytes.failure();
  auto file = split_container(*bytes, label);
  if (!file) return file.failure();
  json doc = json::parse(file->json.begin(), file->json.end(), nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return make_error(label + ": its glTF JSON does not parse");
  GltfKept kept;
  Builder b;
  try {
    std::vector<JointTargets> targets;
    for (const Clip* take : takes) {
      if (Status s = take->validate(); !s) return s.failure("take '" + take->name + "': cannot write an invalid clip: ");
      targets.push_back(joint_targets(doc, *take));
    }
    Buffers buffers(doc, *file, source.parent_path(), false);
    kept.dropped_channels = moving_other_channels(doc, buffers);
    b = repack_without_animations(doc, buffers, source.parent_path(), kept.embedded_images);
    json animations = json::array();
    for (std::size_t k = 0; k < takes.size(); ++k) {
      Result<json> a = animation(b, *takes[k], keys, targets[k]);
      if (!a) return a.failure("take '" + takes[k]->name + "': ");
      animations.push_back(std::move(*a));
    }
    doc["animations"] = std::move(animations);
    undeclare_animation_extensions(doc);
  } catch (const std::exception& e) {
    return make_error(label + ": " + e.what());
  }
  doc["bufferViews"] = std::move(b.views);
  doc["accessors"] = std::move(b.accessors);
  kept.meshes = count_of(doc, "meshes");
  kept.skins = count_of(doc, "skins");
  for (const json& skin : doc.value("skins", json::array())) kept.joints += skin.value("joints", json::array()).size();
  kept.materials = count_of(doc, "materials");
  kept.textures = count_of(doc, "textures");
  kept.images = count_of(doc, "images");
  kept.cameras = count_of(doc, "cameras");
  if (Status s = write_document(std::move(doc), std::move(b.bin), path, binary); !s) return s.failure();
  return kept;
}

}  // namespace rotinterp
