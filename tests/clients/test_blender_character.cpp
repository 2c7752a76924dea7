// Blender (Debian's 3.4, headless) opens the FBX that `resample` writes from an FBX
// character as it opens the source: the same meshes (vertex and face counts,
// vertex groups, materials), one action per take, and the skin deformed the same
// at the first, middle and last time, within 0.1 % of the figure's height, with
// nothing fitted. assimp reads every output too.
#include "blender_character.h"

#include <gtest/gtest.h>

namespace rotinterp::test {
namespace {

TEST(BlenderCharacter, ResampledFbxCharactersDeformAsTheirSources) {
  // 24 Hz and 30 Hz sources at 30 Hz: every 1/6 s is a key of both.
  const TempDir dir;
  expect_same_character({{"fbx/ufbx_maya_kenney_character_7700_binary.fbx", "resample --fps 30"},
                         {"fbx/digitalrune_Dude.fbx", "resample --fps 30"},
                         {"fbx/digitalrune_Marine_Run.fbx", "resample --fps 30"}},
                        1.0 / 6.0, dir.path(), ".fbx");
}

}  // namespace
}  // namespace rotinterp::test
