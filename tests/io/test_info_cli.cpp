// `rotinterp info`: what a user reads about a clip, in text and JSON.
#include "io_test_util.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace rotinterp {
namespace {

using test::kData;

TEST(InfoCli, JsonDescribesTheBvhLayoutFramesAndRate) {
  const test::CliResult r = test::run_cli("info --json '" + (kData / "bvh" / "cmu_01_01.bvh").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "bvh");
  EXPECT_EQ(j["frames"], 2752);
  EXPECT_DOUBLE_EQ(j["frame_time_s"].get<double>(), 0.0083333);
  EXPECT_EQ(j["joints"].size(), 31u);
  EXPECT_EQ(j["end_sites"], 7);
  EXPECT_EQ(j["joints"][0]["name"], "Hips");
  EXPECT_EQ(j["joints"][0]["channels"],
            nlohmann::json({"Xposition", "Yposition", "Zposition", "Zrotation", "Yrotation", "Xrotation"}));
  EXPECT_EQ(j["joints"][1]["parent"], "Hips");
  EXPECT_EQ(j["translation_tracks"], nlohmann::json({"Hips"}));
  EXPECT_EQ(j["animations"].size(), 1u);
  EXPECT_NEAR(j["duration_s"].get<double>(), 2751 * 0.0083333, 1e-9);
}

TEST(InfoCli, TextShowsTheExactFrameTimeTheJointTreeAndFbxOddities) {
  const test::CliResult bvh = test::run_cli("info '" + (kData / "bvh" / "cmu_01_01.bvh").string() + "'");
  ASSERT_EQ(bvh.exit_code, 0) << bvh.err;
  EXPECT_NE(bvh.out.find("(frame time .0083333 s)"), std::string::npos) << bvh.out;
  EXPECT_NE(bvh.out.find("\n    LHipJoint  [Zrotation Yrotation Xrotation]  2752 rotation keys\n"), std::string::npos) << bvh.out;
  EXPECT_NE(bvh.out.find("translation tracks: Hips\n"), std::string::npos);

  const test::CliResult fbx = test::run_cli("info '" + (kData / "fbx" / "digitalrune_Marine_Run.fbx").string() + "'");
  ASSERT_EQ(fbx.exit_code, 0) << fbx.err;
  EXPECT_NE(fbx.out.find("*0 'Run'"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("24 $AssimpFbx$ helper nodes folded"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("unit:        0.01 m per unit"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("joint(s) without rotation keys (static)"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("non-uniform key spacing"), std::string::npos) << fbx.out;
}

}  // namespace
}  // namespace rotinterp
