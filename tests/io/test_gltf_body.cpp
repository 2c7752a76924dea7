// A character's body written into our glTF (src/io/gltf/gltf_body.h): four weights
// per vertex, normalized, the loss said; inverse bind matrices that put the source's
// bind pose on our joints; images embedded; rigid and static meshes placed; and a
// body that is no mesh refused with nothing written. (Blender's view of FBX
// characters written so: tests/clients/test_blender_character.cpp.)
#include "io_test_util.h"
#include "rotinterp/io/gltf/gltf_write.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>

namespace rotinterp {
namespace {

using nlohmann::json;

// Six joints in a chain along y, 10 units apart (centimetres), each turned about z.
Clip chain() {
  Clip c;
  c.name = "take";
  for (int j = 0; j < 6; ++j) {
    c.skeleton.joints.push_back({"J" + std::to_string(j), j - 1, Vec3(j ? 0.0 : 5.0, j ? 10.0 : 0.0, 0.0),
                                 Quat(Eigen::AngleAxisd(0.1 * j, Vec3::UnitZ()))});
    c.rotations.push_back({{0.0, 1.0}, {Quat::Identity(), Quat(Eigen::AngleAxisd(0.5, Vec3::UnitX()))}});
    c.translations.push_back(std::nullopt);
  }
  c.frame_time = 1.0;
  c.unit = {0.01, UnitOrigin::declared, "cm"};
  return c;
}

RowMajor4 row_major(const Eigen::Matrix4d& m) {
  RowMajor4 out{};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) out[static_cast<std::size_t>(4 * r + k)] = m(r, k);
  return out;
}

// The mesh's world at bind time: moved and turned against the joints' rest pose.
Eigen::Matrix4d mesh_world() {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  m.topRightCorner<3, 1>() = Vec3(2.0, -4.0, 7.0);
  return m;
}

// The mesh's world at bind time as bone j sees it: where the bind pose differs from
// the rest pose, turned a little against the mesh node's world at rest.
Eigen::Matrix4d bind_world(int j) {
  Eigen::Matrix4d turn = Eigen::Matrix4d::Identity();
  turn.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.05 * j, Vec3::UnitY()).toRotationMatrix();
  return turn * mesh_world();
}

// In metres: D·m·D⁻¹ for a transform m in centimetres.
Eigen::Matrix4d metres(Eigen::Matrix4d m) {
  m.topRightCorner<3, 1>() *= 0.01;
  return m;
}

// One triangle: vertex 0 weighs six bones, vertex 1 two that sum to 0.5, vertex 2 none.
CharacterBody body() {
  CharacterBody b;
  BodyMesh mesh;
  mesh.name = "Tri";
  mesh.world = row_major(mesh_world());
  mesh.parent_joint = "J2";
  BodyPart part;
  part.positions = {0, 0, 0, 10, 0, 0, 0, 10, 0};
  part.normals = {0, 0, 2, 0, 0, 1, 0, 0, 0};  // one too long, one zero: both made unit
  part.uvs = {0, 0, 1, 0, 0, 1};
  part.triangles = {0, 1, 2};
  part.material = 0;
  const float w0[] = {0.06f, 0.3f, 0.2f, 0.25f, 0.15f, 0.04f};  // heaviest: J1, J3, J2, J4
  for (int j = 0; j < 6; ++j) {
    BodyBone bone;
    bone.joint = "J" + std::to_string(j);
    bone.mesh_to_world = row_major(bind_world(j));
    bone.vertices = {0};
    bone.weights = {w0[j]};
    if (j == 0 || j == 5) bone.vertices.push_back(1), bone.weights.push_back(0.25f);
    part.bones.push_back(bone);
  }
  mesh.parts.push_back(part);
  b.meshes.push_back(mesh);
  b.materials.push_back({"Skin", {0.5, 0.25, 1.0, 1.0}, 0});
  b.images.push_back({"skin.png", "image/png", std::string("\x89PNG\r\n\x1a\n", 8) + "pixels"});
  b.notes.push_back("texture 'other.tga' of material 'Skin' is not beside the file; its colour is kept");
  return b;
}

struct Written {
  json doc;
  std::string bin;
  GltfBodyWritten said;
};

Written write(const Clip& clip, const CharacterBody& b, const test::TempDir& dir) {
  const Result<GltfBodyWritten> said = write_gltf({&clip}, dir / "out.gltf", false, {}, b);
  EXPECT_TRUE(said) << said.error();
  Written w{json::parse(test::read_text(dir / "out.gltf")), "", said ? *said : GltfBodyWritten{}};
  w.bin = test::read_text(dir / w.doc["buffers"][0]["uri"].get<std::string>());
  return w;
}

template <class T>
std::vector<T> accessor(const Written& w, std::size_t index) {
  const json& a = w.doc["accessors"][index];
  const json& v = w.doc["bufferViews"][a["bufferView"].get<std::size_t>()];
  const std::size_t width = a["type"] == "SCALAR" ? 1 : a["type"] == "VEC2" ? 2 : a["type"] == "VEC3" ? 3 : a["type"] == "VEC4" ? 4 : 16;
  std::vector<T> out(width * a["count"].get<std::size_t>());
  std::memcpy(out.data(), w.bin.data() + v["byteOffset"].get<std::size_t>(), out.size() * sizeof(T));
  return out;
}

TEST(GltfBody, FourHeaviestWeightsKeptNormalizedAndTheLossSaid) {
  const test::TempDir dir;
  const Written w = write(chain(), body(), dir);
  ASSERT_EQ(w.doc["meshes"].size(), 1u);
  const json& attributes = w.doc["meshes"][0]["primitives"][0]["attributes"];
  const json& skin = w.doc["skins"][1];  // skins[0]: the skeleton's own
  const auto joints = accessor<std::uint16_t>(w, attributes["JOINTS_0"]);
  const auto weights = accessor<float>(w, attributes["WEIGHTS_0"]);
  auto joint = [&](std::size_t v, std::size_t i) { return skin["joints"][joints[4 * v + i]].get<int>(); };
  // Vertex 0: J1 0.3, J3 0.25, J2 0.2, J4 0.15 of 0.9 kept.
  const int heaviest[] = {1, 3, 2, 4};
  const float kept[] = {0.3f, 0.25f, 0.2f, 0.15f};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(joint(0, i), heaviest[i]);
    EXPECT_NEAR(weights[i], kept[i] / 0.9f, 1e-6);
  }
  // Vertex 1: J0 and J5, 0.25 each, made 0.5 each; vertex 2: its mesh's joint, J2.
  EXPECT_NEAR(weights[4] + weights[5], 1.0, 1e-6);
  EXPECT_NEAR(weights[4], 0.5, 1e-6);
  EXPECT_EQ(joint(2, 0), 2);
  EXPECT_EQ(weights[8], 1.0f);
  // J0 and J5 weigh vertex 1 only, yet are joints; no bone weighs nothing here.
  EXPECT_EQ(skin["joints"].size(), 6u);
  const std::string notes = [&] {
    std::string s;
    for (const std::string& n : w.said.notes) s += n + "\n";
    return s;
  }();
  EXPECT_NE(notes.find("mesh 'Tri': 1 vertex has more than 4 weights; the 4 heaviest kept, normalized"), std::string::npos) << notes;
  EXPECT_NE(notes.find("mesh 'Tri': 1 vertex's skin weights do not sum to 1; normalized"), std::string::npos) << notes;
  EXPECT_NE(notes.find("mesh 'Tri': 1 vertex has no weight; moved with joint 'J2'"), std::string::npos) << notes;
  EXPECT_NE(notes.find("other.tga"), std::string::npos) << notes;
  EXPECT_EQ(w.said.kept, "1 mesh, 1 skin (6 bones), 1 material, 1 texture kept");
  // Normals turned as the mesh node turns them and made unit length (the spec asks
  // it); a zero one points up z.
  const auto normals = accessor<float>(w, attributes["NORMAL"]);
  const Vec3 up = mesh_world().topLeftCorner<3, 3>() * Vec3::UnitZ();
  ASSERT_EQ(normals.size(), 9u);
  for (std::size_t v = 0; v < 2; ++v)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(normals[3 * v + static_cast<std::size_t>(c)], up[c], 1e-7) << v;
  EXPECT_EQ(std::vector<float>(normals.begin() + 6, normals.end()), (std::vector<float>{0, 0, 1}));
  // glTF's v runs down the image.
  EXPECT_EQ(accessor<float>(w, attributes["TEXCOORD_0"]), (std::vector<float>{0, 1, 1, 1, 0, 0}));
}

// Vertices are written where the mesh node puts them (D·W·v: true size, without
// skinning), and J·IBM = D·M·W⁻¹·D⁻¹, so that each joint at rest puts a written vertex
// where the source's bind pose puts it through that bone: J·IBM·(D·W·v) = D·M·v.
TEST(GltfBody, VerticesAtTrueSizeAndInverseBindMatricesPutTheSourcesBindPoseOnOurJoints) {
  const test::TempDir dir;
  const Clip clip = chain();
  const CharacterBody b = body();
  const Written w = write(clip, b, dir);
  const json& skin = w.doc["skins"][1];
  const auto ibm = accessor<float>(w, skin["inverseBindMatrices"]);
  const auto written = accessor<float>(w, w.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]);
  const std::vector<float>& source = b.meshes[0].parts[0].positions;
  for (std::size_t v = 0; v < 3; ++v) {
    const Vec3 local(source[3 * v], source[3 * v + 1], source[3 * v + 2]);
    const Vec3 expected = (metres(mesh_world()) * (local * 0.01).homogeneous()).head<3>();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(written[3 * v + static_cast<std::size_t>(c)], expected[c], 1e-7) << v;
  }
  const WorldPose rest = rest_pose(clip.skeleton);
  for (std::size_t s = 0; s < skin["joints"].size(); ++s) {
    const std::size_t j = skin["joints"][s].get<std::size_t>();
    Eigen::Matrix4d world = Eigen::Matrix4d::Identity(), inverse;
    world.topLeftCorner<3, 3>() = rest.rotation[j].toRotationMatrix();
    world.topRightCorner<3, 1>() = rest.position[j] * 0.01;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) inverse(r, c) = ibm[16 * s + static_cast<std::size_t>(4 * c + r)];
    const Eigen::Matrix4d expected = metres(bind_world(static_cast<int>(j))) * metres(mesh_world()).inverse();
    EXPECT_LT((world * inverse - expected).cwiseAbs().maxCoeff(), 1e-6) << clip.skeleton.joints[j].name;
    for (std::size_t v = 0; v < 3; ++v) {
      const Vec3 at(written[3 * v], written[3 * v + 1], written[3 * v + 2]);
      const Vec3 local(source[3 * v], source[3 * v + 1], source[3 * v + 2]);
      const Vec3 bound = (metres(bind_world(static_cast<int>(j))) * (local * 0.01).homogeneous()).head<3>();
      EXPECT_LT(((world * inverse * at.homogeneous()).head<3>() - bound).norm(), 1e-6) << j << " " << v;
    }
  }
}

// A mirroring node transform turns the triangles' winding over, so that they face
// the way they faced in the source.
TEST(GltfBody, AMirroredMeshKeepsItsFacesTurnedOut) {
  const test::TempDir dir;
  CharacterBody b = body();
  Eigen::Matrix4d mirror = mesh_world();
  mirror.col(0) *= -1.0;
  b.meshes[0].world = row_major(mirror);
  const Written w = write(chain(), b, dir);
  const json& primitive = w.doc["meshes"][0]["primitives"][0];
  EXPECT_EQ(accessor<std::uint32_t>(w, primitive["indices"]), (std::vector<std::uint32_t>{0, 2, 1}));
  const Written plain = write(chain(), body(), dir);
  EXPECT_EQ(accessor<std::uint32_t>(plain, plain.doc["meshes"][0]["primitives"][0]["indices"]),
            (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(GltfBody, ImagesAreEmbeddedWithTheirMimeTypeAndMaterialsKeepTheirColour) {
  const test::TempDir dir;
  const CharacterBody b = body();
  const Written w = write(chain(), b, dir);
  ASSERT_EQ(w.doc["images"].size(), 1u);
  const json& image = w.doc["images"][0];
  EXPECT_EQ(image["mimeType"], "image/png");
  const json& view = w.doc["bufferViews"][image["bufferView"].get<std::size_t>()];
  EXPECT_EQ(w.bin.substr(view["byteOffset"].get<std::size_t>(), view["byteLength"].get<std::size_t>()), b.images[0].bytes);
  const json& pbr = w.doc["materials"][0]["pbrMetallicRoughness"];
  EXPECT_EQ(pbr["baseColorFactor"], json({0.5, 0.25, 1.0, 1.0}));
  EXPECT_EQ(w.doc["textures"][pbr["baseColorTexture"]["index"].get<std::size_t>()]["source"], 0);
  EXPECT_EQ(w.doc["meshes"][0]["primitives"][0]["material"], 0);
}

TEST(GltfBody, ARigidMeshFollowsTheJointAboveItAndOneWithNoneStaysWhereItIs) {
  const test::TempDir dir;
  CharacterBody b = body();
  b.meshes[0].parts[0].bones.clear();
  BodyMesh loose = b.meshes[0];
  loose.name = "Loose";
  loose.parent_joint.clear();
  b.meshes.push_back(loose);
  const Written w = write(chain(), b, dir);
  ASSERT_EQ(w.doc["meshes"].size(), 2u);
  const json& nodes = w.doc["nodes"];
  const json& rigid = nodes[nodes.size() - 2];
  const json& still = nodes[nodes.size() - 1];
  ASSERT_TRUE(rigid.contains("skin"));
  EXPECT_EQ(w.doc["skins"][rigid["skin"].get<std::size_t>()]["joints"], json({2}));
  EXPECT_FALSE(still.contains("skin"));
  EXPECT_FALSE(still.contains("matrix"));  // its vertices are where its node put them: vertex 0 at the node's origin
  const auto moved = accessor<float>(w, w.doc["meshes"][1]["primitives"][0]["attributes"]["POSITION"]);
  EXPECT_NEAR(moved[0], 0.02, 1e-7);
  EXPECT_NEAR(moved[1], -0.04, 1e-7);
  EXPECT_NEAR(moved[2], 0.07, 1e-7);
  // The rigid mesh's one joint binds it where the node puts it: J·IBM = identity.
  const auto ibm = accessor<float>(w, w.doc["skins"][rigid["skin"].get<std::size_t>()]["inverseBindMatrices"]);
  const WorldPose rest = rest_pose(chain().skeleton);
  Eigen::Matrix4d joint = Eigen::Matrix4d::Identity(), inverse;
  joint.topLeftCorner<3, 3>() = rest.rotation[2].toRotationMatrix();
  joint.topRightCorner<3, 1>() = rest.position[2] * 0.01;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) inverse(r, c) = ibm[static_cast<std::size_t>(4 * c + r)];
  EXPECT_LT((joint * inverse - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_EQ(w.said.kept, "2 meshes, 1 skin (1 bone), 1 material, 1 texture kept");
  EXPECT_EQ(w.said.notes.size(), 1u);  // the texture's; a rigid mesh's vertices are no repair
}

TEST(GltfBody, ABodyThatIsNoMeshIsRefusedAndNothingIsWritten) {
  const test::TempDir dir;
  const Clip clip = chain();
  for (int fault = 0; fault < 3; ++fault) {
    CharacterBody b = body();
    BodyPart& part = b.meshes[0].parts[0];
    if (fault == 0) part.triangles[2] = 3;  // past the vertices
    if (fault == 1) part.positions[4] = NAN;
    if (fault == 2) part.uvs.pop_back();
    const Result<GltfBodyWritten> said = write_gltf({&clip}, dir / "out.glb", true, {}, b);
    ASSERT_FALSE(said);
    EXPECT_NE(said.error().find("mesh 'Tri' is not a mesh"), std::string::npos) << said.error();
    EXPECT_TRUE(dir.files().empty());
  }
}

// Through write_clips from an FBX character: takes of different skeletons are refused
// (the body's skins name one), and an FBX 6.1 source, whose meshes no reader of ours
// reads, is written as its skeleton with the reason said.
TEST(GltfBody, AnFbxCharacterAsGlbRefusesTwoSkeletonsAndSaysWhenItHasNoBody) {
  const test::TempDir dir;
  const std::string marine = (test::kData / "fbx/digitalrune_Marine_Run.fbx").string();
  const Result<Clip> run = read_clip(marine);
  ASSERT_TRUE(run) << run.error();
  Clip other = *run;
  other.name = "Other";
  other.skeleton.joints.back().name = "Tail";
  std::vector<std::string> warnings;
  WriteOptions options;
  options.source = marine;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  const Status two = write_clips({*run, other}, dir / "two.glb", options);
  ASSERT_FALSE(two);
  EXPECT_NE(two.error().find("take 'Other' has another skeleton"), std::string::npos) << two.error();
  EXPECT_TRUE(dir.files().empty());

  const std::string sausage = (test::kData / "fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx").string();
  const Result<Clip> wiggle = read_clip(sausage);
  ASSERT_TRUE(wiggle) << wiggle.error();
  options.source = sausage;
  ASSERT_TRUE(write_clip(*wiggle, dir / "sausage.glb", options));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("the character is not kept: an FBX 6.1 file"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("are not written"), std::string::npos) << warnings[1];
}

}  // namespace
}  // namespace rotinterp
