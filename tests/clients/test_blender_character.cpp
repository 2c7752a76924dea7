// Blender (Debian's 3.4, headless) opens the FBX that `resample` and `reduce` write
// from an FBX character as it opens the source: the same meshes (vertex and face
// counts, vertex groups, materials), one action per take written, and the skin
// deformed the same at the first, middle and last time of each take, within 0.1 %
// of the figure's height, with nothing fitted. assimp reads every output too.
#include "blender_character.h"
#include "client_fixture.h"
#include "rotinterp/io/fbx/fbx_character.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace rotinterp::test {
namespace {

TEST(BlenderCharacter, ResampledFbxCharactersDeformAsTheirSources) {
  // 24 Hz and 30 Hz sources at 30 Hz: every 1/6 s is a key of both. XboxAvatars
  // (15 meshes) states no CustomFrameRate: the one we add must be labelled as
  // Blender's importer asserts ("Number"), or it refuses the file. Its take is named
  // so that its actions are not counted: the source also keys five group nodes
  // (BOY, GIRL, …) that are no joints of the clip, with constant curves we drop.
  const TempDir dir;
  expect_same_character({{"fbx/ufbx_maya_kenney_character_7700_binary.fbx", "resample --fps 30", ""},
                         {"fbx/digitalrune_Dude.fbx", "resample --fps 30", ""},
                         {"fbx/digitalrune_Marine_Run.fbx", "resample --fps 30", ""},
                         {"fbx/digitalrune_XboxAvatars_Jump.fbx", "resample --fps 30", "Take 001|BaseLayer"}},
                        1.0 / 6.0, dir.path(), ".fbx");
}

TEST(BlenderCharacter, ReducedFbxCharactersDeformAsTheirSources) {
  const TempDir dir;
  // Marine_Run is 0.23 m tall: 0.05 mm is a fifth of 0.1 % of it.
  const std::string reduce = "reduce --tolerance 0.05deg,0.05mm";
  expect_same_character({{"fbx/ufbx_maya_kenney_character_7700_binary.fbx", reduce, ""},
                         {"fbx/digitalrune_Dude.fbx", reduce, ""},
                         {"fbx/digitalrune_Marine_Run.fbx", reduce, ""}},
                        1.0 / 6.0, dir.path(), ".fbx");
}

// A character Blender makes itself (blender_nla_rig.py, skinned): two takes. Every
// take resampled into one file; each take reduced into a file of its own, which
// holds that take alone.
TEST(BlenderCharacter, EveryTakeOfABlenderMadeCharacterDeformsAsItsSource) {
  const TempDir dir;
  const std::string rig = make_blender_rig(dir.path(), true) + ".fbx";
  const std::string reduce = "reduce --tolerance 0.05deg,0.05mm --anim ";
  expect_same_character({{rig, "resample --anim all --fps 30", ""},
                         {rig, "resample --anim all --fps 24", ""},
                         {rig, "resample --anim 1 --fps 30", "Rig|Wave"},
                         {rig, reduce + "0", "Rig|Walk"},
                         {rig, reduce + "1", "Rig|Wave"}},
                        1.0 / 6.0, dir.path(), ".fbx");
}

// FBX in, GLB out: the body comes through assimp (meshes, skins, materials, the rig's
// embedded PNG) and Blender's glTF importer deforms it as its FBX importer deforms
// the source. Across formats a mesh compares by its distinct positions and triangles
// (blender_character.py), a take by its name.
TEST(BlenderCharacter, FbxCharactersWrittenAsGlbDeformAsTheirSources) {
  const TempDir dir;
  const std::string rig = make_blender_rig(dir.path(), true) + ".fbx";
  const std::string reduce = "reduce --tolerance 0.05deg,0.05mm";
  expect_same_character({{"fbx/ufbx_maya_kenney_character_7700_binary.fbx", "resample --fps 30", ""},
                         {"fbx/digitalrune_Dude.fbx", "resample --fps 30", ""},
                         {"fbx/digitalrune_Marine_Run.fbx", "resample --fps 30", ""},
                         {"fbx/ufbx_maya_kenney_character_7700_binary.fbx", reduce, ""},
                         {"fbx/digitalrune_Dude.fbx", reduce, ""},
                         {"fbx/digitalrune_Marine_Run.fbx", reduce, ""},
                         {rig, "resample --anim all --fps 30", ""},
                         {rig, reduce + " --anim 1", "Rig|Wave"}},
                        1.0 / 6.0, dir.path(), ".glb");
}

// An inconsistent source, made from Marine_Run in memory: one with no bind pose, one
// whose first cluster lost its bone, one whose first cluster's weights are halved.
// The summary states each (a repair, or what readers do instead), and Blender opens
// all three: the first deforms as the source, the second has the same mesh with that
// bone's vertex group gone, the third the same mesh. assimp reads all three.
TEST(BlenderCharacter, AnInconsistentCharacterIsRepairedOrSaidAndBlenderOpensIt) {
  const TempDir dir;
  const std::string source = (kData / "fbx/digitalrune_Marine_Run.fbx").string();
  const Result<Clip> clip = read_clip(source);
  ASSERT_TRUE(clip) << clip.error();
  auto nodes = [](FbxCharacter& c, const char* name) -> std::vector<FbxNode>& {
    return std::find_if(c.doc.nodes.begin(), c.doc.nodes.end(), [&](const FbxNode& n) { return n.name == name; })->children;
  };
  auto write = [&](const FbxCharacter& character, const std::string& name, const std::string& said) {
    const Result<FbxCharacterTake> take = fbx_character_take(*clip, character, &character.animation.takes.front());
    EXPECT_TRUE(take) << take.error();
    const Result<FbxCharacterFile> file = encode_fbx_character(character, {*take}, std::nullopt, FbxEncoding::binary);
    EXPECT_TRUE(file) << file.error();
    EXPECT_NE(file->kept.text().find(said), std::string::npos) << file->kept.text();
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary).write(file->bytes.data(), static_cast<std::streamsize>(file->bytes.size()));
    expect_assimp_reads(path);
    return path;
  };
  Result<FbxCharacter> no_pose = read_fbx_character(source);
  ASSERT_TRUE(no_pose) << no_pose.error();
  std::vector<FbxNode>& objects = nodes(*no_pose, "Objects");
  objects.erase(std::remove_if(objects.begin(), objects.end(), [](const FbxNode& o) { return o.name == "Pose"; }), objects.end());
  const std::string unposed = write(*no_pose, "no_bind_pose.fbx", "no bind pose");

  Result<FbxCharacter> lost_bone = read_fbx_character(source);
  ASSERT_TRUE(lost_bone) << lost_bone.error();
  std::set<std::int64_t> clusters;
  std::map<std::int64_t, std::string> models;
  for (const FbxNode& o : nodes(*lost_bone, "Objects")) {
    if (o.name == "Deformer" && o.properties.at(2).text == "Cluster") clusters.insert(o.properties[0].integer);
    if (o.name == "Model") models[o.properties[0].integer] = o.properties.at(1).text.substr(0, o.properties[1].text.find('\0'));
  }
  std::vector<FbxNode>& links = nodes(*lost_bone, "Connections");
  const auto bone_link = std::find_if(links.begin(), links.end(), [&](const FbxNode& c) {
    return models.count(c.properties.at(1).integer) && clusters.count(c.properties.at(2).integer);
  });
  ASSERT_NE(bone_link, links.end());
  const std::string lost = models[bone_link->properties[1].integer];
  links.erase(bone_link);
  const std::string unboned = write(*lost_bone, "lost_bone.fbx", "1 cluster linked to no bone dropped");

  Result<FbxCharacter> light = read_fbx_character(source);  // one cluster's weights halved
  ASSERT_TRUE(light) << light.error();
  for (FbxNode& o : nodes(*light, "Objects"))
    if (o.name == "Deformer" && o.properties.at(2).text == "Cluster") {
      for (FbxNode& c : o.children)
        if (c.name == "Weights")
          for (double& w : c.properties.at(0).numbers) w *= 0.5;
      break;
    }
  const std::string halved = write(*light, "halved_weights.fbx", "skin weights do not sum to 1 (kept as the source has them");

  const std::vector<BlenderCharacter> imports =
      blender_characters({{source, unposed}, {source, unboned}, {source, halved}}, 1.0 / 6.0, dir.path());
  const BlenderCharacter& original = imports[0];
  ASSERT_EQ(original.meshes.size(), 1u);
  EXPECT_EQ(imports[1].meshes, original.meshes);
  const PoseDeviation d = pose_deviation(imports[1], original);
  EXPECT_EQ(d.times, 3u);
  EXPECT_LE(d.distance, 1e-3 * d.height);
  ASSERT_EQ(imports[3].meshes.size(), 1u);
  BlenderMesh without = original.meshes.front();
  without.groups.erase(std::remove(without.groups.begin(), without.groups.end(), lost), without.groups.end());
  EXPECT_EQ(without.groups.size() + 1, original.meshes.front().groups.size()) << lost;
  EXPECT_EQ(imports[3].meshes.front(), without);
  EXPECT_EQ(imports[5].meshes, original.meshes);  // opened, the same mesh
  std::printf("[ blender ] no bind pose: worst %.4g mm of %.4g m; cluster of %s dropped: %zu vertex groups of %zu\n",
              d.distance * 1000, d.height, lost.c_str(), imports[3].meshes.front().groups.size(),
              original.meshes.front().groups.size());
}

}  // namespace
}  // namespace rotinterp::test
