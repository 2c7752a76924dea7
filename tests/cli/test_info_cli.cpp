// `rotinterp info`: what a user reads about a clip, in text and JSON.
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

const fs::path kData = ROTINTERP_SHARED_DATA;

// Each test's own empty directory, removed after it.
class InfoCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_info_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(InfoCli, JsonDescribesTheBvhLayoutFramesAndRate) {
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

TEST_F(InfoCli, TextShowsTheExactFrameTimeTheJointTreeAndFbxOddities) {
  const test::CliResult bvh = test::run_cli("info '" + (kData / "bvh" / "cmu_01_01.bvh").string() + "'");
  ASSERT_EQ(bvh.exit_code, 0) << bvh.err;
  EXPECT_NE(bvh.out.find("(frame time .0083333 s)"), std::string::npos) << bvh.out;
  EXPECT_NE(bvh.out.find("\n    LHipJoint  [Zrotation Yrotation Xrotation]  2752 rotation keys\n"), std::string::npos) << bvh.out;
  EXPECT_NE(bvh.out.find("translation tracks: Hips\n"), std::string::npos);

  const test::CliResult fbx = test::run_cli("info '" + (kData / "fbx" / "digitalrune_Marine_Run.fbx").string() + "'");
  ASSERT_EQ(fbx.exit_code, 0) << fbx.err;
  EXPECT_NE(fbx.out.find("*0 'Run'"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("24 $AssimpFbx$ helper nodes folded"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("unit:        cm (declared by the file: FBX UnitScaleFactor 1)"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("joint(s) without rotation keys (static)"), std::string::npos) << fbx.out;
  EXPECT_NE(fbx.out.find("non-uniform key spacing"), std::string::npos) << fbx.out;
}

// One rate recognizer for every command: a BVH "Frame Time: .0333330" is 30 Hz in
// `info` (text and JSON) and in `resample`'s summary; a BVH declares no unit.
TEST_F(InfoCli, InfoAndResampleRecognizeTheSameRateAndBvhDeclaresNoUnit) {
  const fs::path& dir = dir_;
  std::string text = test::slurp(kData / "bvh" / "bvhio_example.bvh");
  const std::size_t at = text.find("Frame Time:");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, text.find('\n', at) - at, "Frame Time: .0333330");
  std::ofstream(dir / "in.bvh", std::ios::binary) << text;
  const test::CliResult info = test::run_cli("info '" + (dir / "in.bvh").string() + "'");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("frame rate:  30 Hz (frame time .0333330 s)"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("unit:        "), std::string::npos) << info.out;
  const test::CliResult json = test::run_cli("info --json '" + (dir / "in.bvh").string() + "'");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["frame_rate"], "30");
  EXPECT_EQ(j["frame_rate_hz"], 30.0);
  EXPECT_TRUE(j["unit"]["metres_per_unit"].is_number());
  EXPECT_NE(j["unit"]["origin"], "declared");  // a BVH states no unit
  const test::CliResult resample = test::run_cli("resample '" + (dir / "in.bvh").string() + "' -o '" + (dir / "out.bvh").string() + "'");
  ASSERT_EQ(resample.exit_code, 0) << resample.err;
  EXPECT_NE(resample.out.find("(30 Hz → 30 Hz)"), std::string::npos) << resample.out;
}

// NTSC outputs of every format read back as the exact 30000/1001.
TEST_F(InfoCli, NtscOutputsReadBackAsTheExactRational) {
  const fs::path& dir = dir_;
  for (const char* ext : {".fbx", ".glb", ".gltf", ".bvh", ".dae"}) {
    const auto out = dir / (std::string("out") + ext);
    const test::CliResult r = test::run_cli("resample '" + (kData / "bvh" / "NC_bandai2_raise-up-both-hands_active_031.bvh").string() +
                                            "' -o '" + out.string() + "' --fps 30000/1001 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const test::CliResult info = test::run_cli("info --json '" + out.string() + "'");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out)["frame_rate"], "30000/1001") << ext;
  }
}

// Dude's keys lie on no grid, but the FBX states 30 fps (GlobalSettings): its frames
// are at that rate, `info` says the file states it, and `resample` without --fps
// keeps it.
TEST_F(InfoCli, FbxOwnFrameRateIsTheDefaultWhereKeysGiveNone) {
  const std::string in = (kData / "fbx" / "digitalrune_Dude.fbx").string();
  const test::CliResult info = test::run_cli("info '" + in + "'");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("frame rate:  30 Hz (frame time 0.0333333333 s), stated by the file"), std::string::npos) << info.out;
  const test::CliResult json = test::run_cli("info --json '" + in + "'");
  EXPECT_EQ(nlohmann::json::parse(json.out)["file_frame_rate_hz"], 30.0);
  const fs::path& dir = dir_;
  const test::CliResult r = test::run_cli("resample '" + in + "' -o '" + (dir / "out.bvh").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("39 → 39 frames (30 Hz → 30 Hz)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rotinterp
