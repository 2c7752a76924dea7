// --loop on the command line: info reports the cycle and the joint that misses
// closure (text and JSON); resample --loop writes one period and says how; bad words
// are usage errors and a clip that is no cycle is refused with the reason.
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using rotinterp::test::run_cli;

const std::string kRun = (fs::path(ROTINTERP_SHARED_DATA) / "fbx/digitalrune_Marine_Run.fbx").string();

fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("rotinterp_loop_" + std::to_string(::getpid()) + "_" + name);
}

TEST(LoopCli, InfoReportsTheCycleAndTheJointThatMissesClosure) {
  const auto text = run_cli("info " + kRun);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("cycle:       looks like a cycle (closed form: 40 frames"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("L_Arm 4.39°"), std::string::npos) << text.out;
  const auto json = run_cli("info --json " + kRun);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto cycle = nlohmann::json::parse(json.out).at("cycle");
  EXPECT_TRUE(cycle.at("looks_like_cycle").get<bool>());
  EXPECT_EQ(cycle.at("form"), "closed");
  ASSERT_EQ(cycle.at("joints_missing_closure").size(), 1u);
  EXPECT_EQ(cycle.at("joints_missing_closure")[0].at("joint"), "L_Arm");
  EXPECT_NEAR(cycle.at("joints_missing_closure")[0].at("angle_deg").get<double>(), 4.39, 0.01);
}

TEST(LoopCli, ResampleLoopWritesOnePeriodAtTheNewRateAndSaysHow) {
  const fs::path out = temp_file("run25.bvh");
  const auto r = run_cli("resample " + kRun + " -o " + out.string() + " --fps 25 --loop");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("41 → 34 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cycle (closed form): 40 → 33 frames per period of 1.333 s; period -1.00% (1.32 s)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1 joint misses closure (a pop at the seam in the source): L_Arm 4.39°, kept as it is"), std::string::npos) << r.out;
  const auto again = run_cli("info " + out.string());
  EXPECT_NE(again.out.find("looks like a cycle (closed form: 33 frames"), std::string::npos) << again.out;
  fs::remove(out);
}

TEST(LoopCli, BadWordsAreUsageErrorsAndANonCycleIsRefusedWithItsReason) {
  const fs::path out = temp_file("walk.bvh");
  const auto bad = run_cli("resample " + kRun + " -o " + out.string() + " --loop=wrap");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--loop 'wrap': expected auto, closed or open"), std::string::npos) << bad.err;
  const std::string walk = (fs::path(ROTINTERP_SOURCE_DIR) / "samples/walk.bvh").string();
  const auto refused = run_cli("resample " + walk + " -o " + out.string() + " --loop");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("does not look like a cycle"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing half-written";
  const auto forced = run_cli("resample " + walk + " -o " + out.string() + " --loop open -q");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  fs::remove(out);
}

}  // namespace
