// Rigid meshes hanging off animated joints are kept as End Sites, so a figure
// whose nodes all sit at one point still has the file's shape; skinned meshes and
// meshes on the joints themselves add none.
#include "io_test_util.h"
#include "support/box_chain_gltf.h"

#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <string>

namespace rotinterp {
namespace {

TEST(MeshEndSites, BoxesHangingOffJointsAtOnePointBecomeEndSitesAtTheirCentres) {
  test::TempDir dir;
  const auto path = dir / "boxes.gltf";
  test::write_box_chain_gltf(path, 64);
  auto clip = read_clip(path);
  ASSERT_TRUE(clip) << clip.error();
  ASSERT_EQ(clip->skeleton.joints.size(), 64u);
  ASSERT_EQ(clip->skeleton.end_sites.size(), 64u);
  for (std::size_t k = 0; k < 64; ++k) {
    const EndSite& e = clip->skeleton.end_sites[k];
    EXPECT_EQ(clip->skeleton.joints[static_cast<std::size_t>(e.parent)].name, "J" + std::to_string(k));
    EXPECT_EQ(e.name, "Box" + std::to_string(k));
    EXPECT_NEAR((e.offset - Vec3(static_cast<double>(k + 1), 0, 0)).norm(), 0.0, 1e-5);
  }
  const WorldPose rest = rest_pose(clip->skeleton);
  for (const Vec3& p : rest.position) EXPECT_NEAR(p.norm(), 0.0, 1e-9) << "the joints all sit at one point";
  EXPECT_NEAR(skeleton_height(rest), 64.0, 1e-4) << "the figure spans the row of boxes";
}

TEST(MeshEndSites, SkinnedMeshesAndMeshesOnTheAnimatedNodesThemselvesAddNone) {
  for (const char* file : {"/fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx",  // skinned
                           "/fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx",  // the cube is the joint
                           "/fbx/digitalrune_Dude.fbx", "/fbx/ufbx_maya_kenney_character_7700_binary.fbx"}) {
    auto clip = read_clip(std::string(ROTINTERP_SHARED_DATA) + file);
    ASSERT_TRUE(clip) << clip.error();
    EXPECT_EQ(clip->skeleton.end_sites.size(), 0u) << file;
  }
}

}  // namespace
}  // namespace rotinterp
