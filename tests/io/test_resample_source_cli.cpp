// `rotinterp resample --method source`: the importer-process read with curves
// (layered takes and FBX 6.1 included), the summary saying which joints came from
// the curves, one-line refusals.
#include "io_test_util.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rotinterp {
namespace {

TEST(ResampleSourceCli, AKeyedFbxIsWrittenWithItsJointsFromTheCurves) {
  test::TempDir dir;
  const auto out = dir / "run.bvh";
  const test::CliResult r = test::run_cli("resample '" + (test::kData / "fbx/digitalrune_Marine_Run.fbx").string() +
                                          "' -o '" + out.string() + "' --fps 60 -m source");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("method source (36 of "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("joints from the file's curves"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
}

// Layers blended (io/fbx/fbx_transform.h): a joint animated in several layers replays.
TEST(ResampleSourceCli, ALayeredFbxIsWrittenWithItsLayersBlended) {
  test::TempDir dir;
  const auto out = dir / "cubes.bvh";
  const test::CliResult r =
      test::run_cli("resample '" + (test::kData / "fbx/ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx").string() +
                    "' -o '" + out.string() + "' -m source");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("method source (6 of 6 joints from the file's curves"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
}

// FBX 6.1: the clip and its curves both come from our own reader.
TEST(ResampleSourceCli, AnFbx61FileIsWrittenWithItsJointsFromTheTakesCurves) {
  test::TempDir dir;
  const auto out = dir / "sausage.bvh";
  const test::CliResult r =
      test::run_cli("resample '" + (test::kData / "fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx").string() +
                    "' -o '" + out.string() + "' --fps 60 -m source");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("20 → 48 frames (24 Hz → 60 Hz), method source (3 of 4 joints from the file's curves"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
}

// glTF: the samplers replayed on the output grid; BVH: its frames (slerp between them).
TEST(ResampleSourceCli, AGlbAndABvhAreResampledFromTheirOwnMotion) {
  test::TempDir dir;
  const std::string bvh = (test::kData / "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh").string();
  const auto glb = dir / "clip.glb";
  ASSERT_EQ(test::run_cli("resample '" + bvh + "' -o '" + glb.string() + "' -q").exit_code, 0);
  const test::CliResult from_glb =
      test::run_cli("resample '" + glb.string() + "' -o '" + (dir / "from_glb.bvh").string() + "' --fps 60 -m source");
  ASSERT_EQ(from_glb.exit_code, 0) << from_glb.err;
  EXPECT_NE(from_glb.out.find("51 → 101 frames (30 Hz → 60 Hz), method source (22 of 22 joints from the file's "
                              "animation samplers)"),
            std::string::npos)
      << from_glb.out;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "from_glb.bvh"));
  const test::CliResult from_bvh = test::run_cli("resample '" + bvh + "' -o '" + (dir / "from_bvh.fbx").string() + "' -m source");
  ASSERT_EQ(from_bvh.exit_code, 0) << from_bvh.err;
  EXPECT_NE(from_bvh.out.find("method source (22 of 22 joints from the file's frames)"), std::string::npos) << from_bvh.out;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "from_bvh.fbx"));
}

TEST(ResampleSourceCli, AColladaFileIsRefusedInOneLineAndNothingIsWritten) {
  test::TempDir dir;
  const auto dae = dir / "walk.dae";
  ASSERT_EQ(test::run_cli("resample '" + (test::kData / "bvh/bvhio_example.bvh").string() + "' -o '" + dae.string() +
                          "' -q").exit_code, 0);
  const auto out = dir / "run.bvh";
  const test::CliResult r = test::run_cli("resample '" + dae.string() + "' -o '" + out.string() + "' -m source");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(dae.string() + ": --method source replays a file's own motion"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("this is a 'dae' file"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ResampleSourceCli, KeepEveryRangeAndLoopAreUsageErrorsWithSource) {
  test::TempDir dir;
  const std::string in = (test::kData / "fbx/digitalrune_Marine_Run.fbx").string();
  for (const char* extra : {"--keep-every 2", "--range 0:0.5", "--loop closed"}) {
    const test::CliResult r =
        test::run_cli("resample '" + in + "' -o '" + (dir / "x.bvh").string() + "' -m source " + extra);
    EXPECT_EQ(r.exit_code, 2) << extra << ": " << r.err;
    EXPECT_NE(r.err.find("--method source evaluates the file's own motion"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace rotinterp
