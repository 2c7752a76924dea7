// A glTF character in, the same character out (io/gltf/gltf_character.h), on a small
// skinned character built here: a triangle skinned to three joints under a scaled
// armature, a material with a texture whose image is a file beside the .gltf, two
// animations (one also scaling a joint). The output keeps every part but the
// animations byte for byte, packs one buffer with no animation bytes of the source,
// and its animations read back as the clips written.
#include "io_test_util.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <functional>
#include <set>

namespace rotinterp {
namespace {

using nlohmann::json;

// A 1×1 PNG (a real one: readers may decode it).
const unsigned char kPng[] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
                              0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00,
                              0x00, 0x90, 0x77, 0x53, 0xde, 0x00, 0x00, 0x00, 0x0c, 0x49, 0x44, 0x41, 0x54, 0x08,
                              0xd7, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x00, 0x03, 0x01, 0x01, 0x00, 0x18, 0xdd, 0x8d,
                              0xb0, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

// The source's buffer, views and accessors as the test appends them.
struct Bytes {
  std::string bin;
  json views = json::array(), accessors = json::array();

  template <class T>
  std::size_t add(const std::vector<T>& values, int component, const char* type, std::size_t count) {
    views.push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", values.size() * sizeof(T)}});
    bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));  // little-endian hosts
    while (bin.size() % 4) bin.push_back('\0');
    accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", component}, {"count", count}, {"type", type}});
    return accessors.size() - 1;
  }
  std::size_t floats(const std::vector<float>& v, const char* type, std::size_t width) {
    std::size_t a = add(v, 5126, type, v.size() / width);
    if (width == 1) accessors[a]["min"] = {v.front()}, accessors[a]["max"] = {v.back()};
    return a;
  }
};

std::vector<float> quat_z(const std::vector<double>& degrees) {
  std::vector<float> out;
  for (double d : degrees) {
    const double h = d * 3.14159265358979 / 360.0;
    for (double c : {0.0, 0.0, std::sin(h), std::cos(h)}) out.push_back(static_cast<float>(c));
  }
  return out;
}

// The character as a .gltf with its buffer as a data-less file `body.bin` and its
// image `skin.png` beside it, in `dir`. Animation data lies between the mesh's
// (indices first, 6 bytes, so that views after them move), to be left out.
void write_character(const test::TempDir& dir) {
  Bytes b;
  const std::size_t indices = b.add(std::vector<std::uint16_t>{0, 1, 2}, 5123, "SCALAR", 3);
  json walk_samplers = json::array(), walk_channels = json::array();
  auto channel = [&](json& samplers, json& channels, std::size_t node, const char* path, std::size_t in, std::size_t out) {
    samplers.push_back({{"input", in}, {"output", out}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
  };
  const std::size_t walk_times = b.floats({0.0f, 0.5f, 1.0f}, "SCALAR", 1);
  channel(walk_samplers, walk_channels, 2, "rotation", walk_times, b.floats(quat_z({0, 30, 10}), "VEC4", 4));
  channel(walk_samplers, walk_channels, 2, "translation", walk_times,
          b.floats({0, 100, 0, 5, 104, 0, 10, 100, 0}, "VEC3", 3));
  const std::size_t positions = b.floats({-0.2f, 0.9f, 0, 0.2f, 0.9f, 0, 0, 1.6f, 0}, "VEC3", 3);
  b.accessors[positions]["min"] = {-0.2, 0.9, 0}, b.accessors[positions]["max"] = {0.2, 1.6, 0};
  channel(walk_samplers, walk_channels, 3, "rotation", walk_times, b.floats(quat_z({0, -20, 0}), "VEC4", 4));
  channel(walk_samplers, walk_channels, 4, "scale", walk_times, b.floats({1, 1, 1, 1.2f, 1.2f, 1.2f, 1, 1, 1}, "VEC3", 3));
  const std::size_t joints = b.add(std::vector<std::uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, 2, 1, 0, 0}, 5121, "VEC4", 3);
  const std::size_t weights = b.floats({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4", 4);
  json idle_samplers = json::array(), idle_channels = json::array();
  const std::size_t idle_times = b.floats({0.0f, 2.0f}, "SCALAR", 1);
  channel(idle_samplers, idle_channels, 3, "rotation", idle_times, b.floats(quat_z({0, 15}), "VEC4", 4));
  // Inverse bind matrices of Hip (1 m up), Spine (1.5 m), Head (1.9 m): world, metres.
  std::vector<float> ibm;
  for (float y : {1.0f, 1.5f, 1.9f})
    for (float v : {1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, -y, 0.0f, 1.0f})
      ibm.push_back(v);
  const std::size_t inverse_binds = b.floats(ibm, "MAT4", 16);
  json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "rotinterp test"}}},
      {"extras", {{"author", "test"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 1}}}}},
      {"nodes",
       {{{"name", "Body"}, {"mesh", 0}, {"skin", 0}},
        {{"name", "Armature"}, {"scale", {0.01, 0.01, 0.01}}, {"children", {2}}},
        {{"name", "Hip"}, {"translation", {0, 100, 0}}, {"children", {3}}},
        {{"name", "Spine"}, {"translation", {0, 50, 0}}, {"children", {4}}},
        {{"name", "Head"}, {"translation", {0, 40, 0}}}}},
      {"meshes",
       {{{"name", "Body"},
         {"primitives",
          {{{"attributes", {{"POSITION", positions}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
            {"indices", indices},
            {"material", 0}}}}}}},
      {"skins", {{{"joints", {2, 3, 4}}, {"inverseBindMatrices", inverse_binds}, {"skeleton", 2}}}},
      {"materials", {{{"name", "Skin"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
      {"textures", {{{"source", 0}, {"sampler", 0}}}},
      {"samplers", {{{"magFilter", 9729}}}},
      {"images", {{{"uri", "skin.png"}}}},
      {"animations",
       {{{"name", "Walk"}, {"samplers", walk_samplers}, {"channels", walk_channels}},
        {{"name", "Idle"}, {"samplers", idle_samplers}, {"channels", idle_channels}}}},
      {"accessors", b.accessors},
      {"bufferViews", b.views},
      {"buffers", {{{"uri", "body.bin"}, {"byteLength", b.bin.size()}}}}};
  test::write_text(dir / "body.bin", b.bin);
  test::write_text(dir / "skin.png", std::string(reinterpret_cast<const char*>(kPng), sizeof kPng));
  test::write_text(dir / "character.gltf", doc.dump());
}

// A GLB's JSON and BIN chunks.
std::pair<json, std::string> read_glb(const std::filesystem::path& path) {
  const std::string bytes = test::read_text(path);
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  EXPECT_EQ(u32(0), 0x46546C67u);
  EXPECT_EQ(u32(8), bytes.size());
  const std::size_t json_length = u32(12);
  const std::size_t bin_at = 20 + json_length;
  return {json::parse(bytes.substr(20, json_length)), bytes.substr(bin_at + 8, u32(bin_at))};
}

// The bytes an accessor's view holds.
std::string view_bytes(const json& doc, const std::string& bin, std::size_t accessor) {
  const json& view = doc["bufferViews"][doc["accessors"][accessor]["bufferView"].get<std::size_t>()];
  return bin.substr(view["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>());
}

struct Written {
  std::vector<std::string> warnings, kept;
  Status status = Ok{};
};

Written write_from(const std::vector<Clip>& takes, const std::filesystem::path& source, const std::filesystem::path& out) {
  Written w;
  WriteOptions o;
  o.source = source.string();
  o.on_warning = [&](const std::string& s) { w.warnings.push_back(s); };
  o.on_kept = [&](const std::string& s) { w.kept.push_back(s); };
  w.status = takes.size() == 1 ? write_clip(takes.front(), out, o) : write_clips(takes, out, o);
  return w;
}

Clip read_take(const std::filesystem::path& path, const std::string& animation) {
  ReadOptions o;
  o.animation = animation;
  Result<Clip> clip = read_clip(path, o);
  EXPECT_TRUE(clip) << clip.error();
  return clip ? *clip : Clip{};
}

TEST(GltfCharacter, EverythingButTheAnimationsPassesThroughAndTheBufferHoldsNoSourceAnimation) {
  const test::TempDir dir;
  write_character(dir);
  const json source = json::parse(test::read_text(dir / "character.gltf"));
  const std::string source_bin = test::read_text(dir / "body.bin");
  const Clip walk = read_take(dir / "character.gltf", "Walk");
  ASSERT_EQ(walk.source_meshes, 1u);
  const Written w = write_from({walk}, dir / "character.gltf", dir / "out.glb");
  ASSERT_TRUE(w.status) << w.status.error();
  EXPECT_TRUE(w.warnings.empty()) << w.warnings.front();
  ASSERT_EQ(w.kept.size(), 1u);
  EXPECT_EQ(w.kept[0], (dir / "out.glb").string() +
                           ": 1 mesh, 1 skin (3 joints), 1 material, 1 texture, 1 image kept; 1 image embedded from "
                           "files beside the source; dropped: 1 animated scale or morph-weight channel");
  const auto [doc, bin] = read_glb(dir / "out.glb");
  for (const char* kept : {"asset", "extras", "scene", "scenes", "nodes", "materials", "textures", "samplers"})
    EXPECT_EQ(doc[kept], source[kept]) << kept;
  // Meshes and skins differ only by their accessors' numbers; the bytes they name are the source's.
  const json& primitive = doc["meshes"][0]["primitives"][0];
  const json& source_primitive = source["meshes"][0]["primitives"][0];
  for (const char* attribute : {"POSITION", "JOINTS_0", "WEIGHTS_0"})
    EXPECT_EQ(view_bytes(doc, bin, primitive["attributes"][attribute]),
              view_bytes(source, source_bin, source_primitive["attributes"][attribute]))
        << attribute;
  EXPECT_EQ(view_bytes(doc, bin, primitive["indices"]), view_bytes(source, source_bin, source_primitive["indices"]));
  EXPECT_EQ(view_bytes(doc, bin, doc["skins"][0]["inverseBindMatrices"]),
            view_bytes(source, source_bin, source["skins"][0]["inverseBindMatrices"]));
  EXPECT_EQ(doc["skins"][0]["joints"], source["skins"][0]["joints"]);
  // The image is in the buffer, as the file beside the source holds it.
  const json& image = doc["images"][0];
  EXPECT_FALSE(image.contains("uri"));
  EXPECT_EQ(image["mimeType"], "image/png");
  const json& image_view = doc["bufferViews"][image["bufferView"].get<std::size_t>()];
  EXPECT_EQ(bin.substr(image_view["byteOffset"].get<std::size_t>(), image_view["byteLength"].get<std::size_t>()),
            std::string(reinterpret_cast<const char*>(kPng), sizeof kPng));
  // One buffer; every view used once, aligned, and the bytes no more than the views and their padding.
  ASSERT_EQ(doc["buffers"].size(), 1u);
  std::multiset<std::size_t> used;
  for (const json& accessor : doc["accessors"]) used.insert(accessor["bufferView"].get<std::size_t>());
  used.insert(image["bufferView"].get<std::size_t>());
  std::size_t view_bytes_total = 0;
  for (std::size_t v = 0; v < doc["bufferViews"].size(); ++v) {
    EXPECT_EQ(used.count(v), 1u) << "view " << v;
    EXPECT_EQ(doc["bufferViews"][v]["byteOffset"].get<std::size_t>() % 4, 0u) << "view " << v;
    view_bytes_total += doc["bufferViews"][v]["byteLength"].get<std::size_t>();
  }
  EXPECT_LT(bin.size(), view_bytes_total + 4 * doc["bufferViews"].size());
  // One animation, the take written, on the source's nodes.
  ASSERT_EQ(doc["animations"].size(), 1u);
  EXPECT_EQ(doc["animations"][0]["name"], "Walk");
  std::set<std::size_t> targets;
  for (const json& c : doc["animations"][0]["channels"]) targets.insert(c["target"]["node"].get<std::size_t>());
  // Its channels: the nodes the source's Walk animates (Head by its scale), not the still armature.
  EXPECT_EQ(targets, (std::set<std::size_t>{2, 3, 4}));
}

TEST(GltfCharacter, TheWrittenAnimationsReadBackAsTheTakesUnderTheScaledArmature) {
  const test::TempDir dir;
  write_character(dir);
  const std::vector<Clip> takes = {read_take(dir / "character.gltf", "Walk"), read_take(dir / "character.gltf", "Idle")};
  const Written w = write_from(takes, dir / "character.gltf", dir / "out.glb");
  ASSERT_TRUE(w.status) << w.status.error();
  const auto [doc, bin] = read_glb(dir / "out.glb");
  ASSERT_EQ(doc["animations"].size(), 2u);
  // Idle animates Spine alone, in the source and in ours.
  ASSERT_EQ(doc["animations"][1]["channels"].size(), 1u);
  EXPECT_EQ(doc["animations"][1]["channels"][0]["target"]["node"], 3);
  for (std::size_t k = 0; k < takes.size(); ++k) {
    const Clip back = read_take(dir / "out.glb", takes[k].name);
    ASSERT_EQ(back.skeleton.joints.size(), takes[k].skeleton.joints.size());
    const double size = test::skeleton_size(takes[k]);
    for (double t = takes[k].start_time(); t <= takes[k].end_time() + 1e-9; t += 0.125) {
      const WorldPose a = test::pose_at(takes[k], t), b = test::pose_at(back, t);
      for (std::size_t j = 0; j < a.position.size(); ++j)
        EXPECT_LT((a.position[j] - b.position[j]).norm(), 1e-6 * size) << takes[k].name << " joint " << j << " t " << t;
    }
  }
}

TEST(GltfCharacter, AGltfOutputKeepsTheCharacterWithItsOneBufferBesideIt) {
  const test::TempDir dir;
  write_character(dir);
  std::filesystem::create_directory(dir / "out");
  const Written w = write_from({read_take(dir / "character.gltf", "Idle")}, dir / "character.gltf", dir / "out" / "idle.gltf");
  ASSERT_TRUE(w.status) << w.status.error();
  ASSERT_EQ(w.kept.size(), 1u);
  const json doc = json::parse(test::read_text(dir / "out" / "idle.gltf"));
  ASSERT_EQ(doc["buffers"].size(), 1u);
  const std::string bin = test::read_text(dir / "out" / doc["buffers"][0]["uri"].get<std::string>());
  EXPECT_EQ(bin.size(), doc["buffers"][0]["byteLength"].get<std::size_t>());
  EXPECT_EQ(doc["meshes"].size(), 1u);
  ASSERT_EQ(doc["animations"].size(), 1u);
  EXPECT_EQ(doc["animations"][0]["name"], "Idle");
  // The image, a file beside the source and not beside the output, is in the buffer.
  EXPECT_FALSE(doc["images"][0].contains("uri"));
  EXPECT_EQ(view_bytes(doc, bin, doc["skins"][0]["inverseBindMatrices"]).size(), 3u * 64u);
}

TEST(GltfCharacter, AJointWithNoNodeOfItsNameWritesTheSkeletonAloneAndSaysWhy) {
  const test::TempDir dir;
  write_character(dir);
  Clip walk = read_take(dir / "character.gltf", "Walk");
  walk.skeleton.joints.back().name = "Neck";
  const Written w = write_from({walk}, dir / "character.gltf", dir / "out.glb");
  ASSERT_TRUE(w.status) << w.status.error();
  EXPECT_TRUE(w.kept.empty());
  ASSERT_EQ(w.warnings.size(), 2u);
  EXPECT_NE(w.warnings[0].find("the character is not kept: "), std::string::npos) << w.warnings[0];
  EXPECT_NE(w.warnings[0].find("joint 'Neck' has no node of its name"), std::string::npos) << w.warnings[0];
  EXPECT_NE(w.warnings[1].find("are not written"), std::string::npos) << w.warnings[1];
  EXPECT_FALSE(read_glb(dir / "out.glb").first.contains("meshes"));
}

// The source declares KHR_animation_pointer for its animations, which ours replace:
// the declaration goes with them; every other extension stays declared.
TEST(GltfCharacter, AnExtensionOnlyTheReplacedAnimationsUsedIsNoLongerDeclared) {
  const test::TempDir dir;
  write_character(dir);
  const Clip walk = read_take(dir / "character.gltf", "Walk");
  json doc = json::parse(test::read_text(dir / "character.gltf"));
  doc["extensionsUsed"] = {"KHR_animation_pointer", "KHR_materials_emissive_strength"};
  test::write_text(dir / "character.gltf", doc.dump());
  const Written w = write_from({walk}, dir / "character.gltf", dir / "out.glb");
  ASSERT_TRUE(w.status) << w.status.error();
  EXPECT_EQ(read_glb(dir / "out.glb").first["extensionsUsed"], json({"KHR_materials_emissive_strength"}));
  doc["extensionsUsed"] = {"KHR_animation_pointer"};
  test::write_text(dir / "character.gltf", doc.dump());
  ASSERT_TRUE(write_from({walk}, dir / "character.gltf", dir / "out.glb").status);
  EXPECT_FALSE(read_glb(dir / "out.glb").first.contains("extensionsUsed"));
}

TEST(GltfCharacter, WhatCannotBeKeptIsSaidInOneLineAndTheSkeletonIsWritten) {
  // A joint node stored as a matrix (no animation may target it); a buffer view with
  // an extension (it would point into the buffers we rewrite).
  const std::vector<std::pair<std::function<void(json&)>, std::string>> cases = {
      {[](json& doc) {
         doc["nodes"][3].erase("translation");
         doc["nodes"][3]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 50, 0, 1};
       },
       "joint 'Spine' is a node stored as a matrix"},
      {[](json& doc) { doc["bufferViews"][0]["extensions"] = {{"EXT_meshopt_compression", {{"buffer", 0}}}}; },
       "buffer view 0 has extensions"}};
  for (const auto& [edit, why] : cases) {
    const test::TempDir dir;
    write_character(dir);
    const Clip walk = read_take(dir / "character.gltf", "Walk");
    json doc = json::parse(test::read_text(dir / "character.gltf"));
    edit(doc);
    test::write_text(dir / "character.gltf", doc.dump());
    const Written w = write_from({walk}, dir / "character.gltf", dir / "out.glb");
    ASSERT_TRUE(w.status) << w.status.error();
    EXPECT_TRUE(w.kept.empty()) << why;
    ASSERT_FALSE(w.warnings.empty()) << why;
    EXPECT_NE(w.warnings[0].find("the character is not kept: "), std::string::npos) << w.warnings[0];
    EXPECT_NE(w.warnings[0].find(why), std::string::npos) << w.warnings[0];
    EXPECT_EQ(std::count(w.warnings[0].begin(), w.warnings[0].end(), '\n'), 0) << w.warnings[0];
    EXPECT_FALSE(read_glb(dir / "out.glb").first.contains("meshes")) << why;
  }
}

}  // namespace
}  // namespace rotinterp
