// Blender (Debian's 3.4, headless) opens the GLB that `resample` and `reduce` write
// from a GLB character as it opens the source: the same meshes (vertex and face
// counts, vertex groups, materials), one action per take, and the skin deformed the
// same at the first, middle and last time, within 0.1 % of the figure's height, with
// nothing fitted. The sources are the shared FBX characters as Blender's own glTF
// exporter writes them. assimp reads every output too.
#include "blender_character.h"
#include "client_fixture.h"

#include <gtest/gtest.h>

namespace rotinterp::test {
namespace {

TEST(BlenderCharacter, ResampledAndReducedGlbCharactersDeformAsTheirSources) {
  const TempDir dir;
  const std::vector<std::string> characters = {"fbx/ufbx_maya_kenney_character_7700_binary.fbx", "fbx/digitalrune_Dude.fbx",
                                               "fbx/digitalrune_Marine_Run.fbx"};
  std::vector<std::string> exports;
  for (std::size_t i = 0; i < characters.size(); ++i)
    exports.push_back((kData / characters[i]).string()), exports.push_back((dir / ("source" + std::to_string(i) + ".glb")).string());
  run_blender("blender_fbx_to_glb.py", "", exports, dir.path(), "export");
  // 24 Hz and 30 Hz sources at 30 Hz: every 1/6 s is a key of both. Every take is
  // written (--anim all); reduce keeps its sparse keys within a budget far below 0.1 %.
  // As many actions as the source (expect_same_character): Marine_Run has eleven, one
  // per IK handle and foot.
  expect_same_character({{exports[1], "resample --fps 30 --anim all", ""},
                         {exports[3], "resample --fps 30 --anim all", ""},
                         {exports[5], "resample --fps 30 --anim all", ""},
                         {exports[3], "reduce --tolerance 0.05deg,0.2mm", ""}},
                        1.0 / 6.0, dir.path(), ".glb");
}

// The two-take character Blender makes (blender_nla_rig.py, skinned, its PNG texture
// embedded) as Blender's glTF exporter writes it: both takes resampled into one GLB,
// one take reduced into a GLB of its own.
TEST(BlenderCharacter, EveryTakeOfABlenderMadeGlbCharacterDeformsAsItsSource) {
  const TempDir dir;
  const std::string rig = make_blender_rig(dir.path(), true) + ".glb";
  const std::vector<BlenderCharacter> imports =
      expect_same_character({{rig, "resample --anim all --fps 30", ""},
                             {rig, "reduce --tolerance 0.05deg,0.05mm --anim 1", "Wave"}},
                            1.0 / 6.0, dir.path(), ".glb");
  ASSERT_EQ(imports.size(), 4u);
  EXPECT_EQ(imports[0].takes, (std::set<std::string>{"Walk", "Wave"}));
}

}  // namespace
}  // namespace rotinterp::test
