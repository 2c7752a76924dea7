// Files as they are: a static mesh is described by info and refused by eval in one
// line; a BVH is described in its own words (frames, Frame Time, CHANNELS); reduce
// keeps the exact rate as resample does (issue 28).
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const std::string kWalk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";

class StaticFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_static_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // A triangle: a file assimp reads that holds a mesh and no animation.
    std::ofstream(dir_ / "tri.obj") << "o Tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(StaticFiles, InfoOnAStaticMeshSaysWhatItHoldsAndSucceeds) {
  const auto r = run_cli("info " + path("tri.obj"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("animations:  0 (no animation"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("holds:       1 mesh, "), std::string::npos) << r.out;
  const auto j = run_cli("info --json " + path("tri.obj"));
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["no_animation"], true);
  EXPECT_EQ(doc["animations"].size(), 0u);
}

TEST_F(StaticFiles, EvalOnAStaticMeshSaysSoInOneLineAndPrintsNoTable) {
  const auto r = run_cli("eval " + path("tri.obj") + " -o " + path("ev"));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("nothing to evaluate: " + path("tri.obj") + " holds no animation"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "") << "no empty table";
}

TEST(BvhInfo, ATakeIsDescribedInTheFilesOwnWords) {
  const auto r = run_cli("info " + kWalk);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // walk.bvh: 31 joints, 6 channels at the root and 3 at the other 30 → 96 CHANNELS.
  std::ifstream in(kWalk);
  std::string line, frame_time;
  std::size_t channels = 0;
  while (std::getline(in, line)) {
    if (const auto at = line.find("CHANNELS "); at != std::string::npos) channels += std::stoul(line.substr(at + 9));
    if (line.rfind("Frame Time:", 0) == 0) frame_time = line.substr(line.find_first_not_of(" \t", 11));
  }
  while (!frame_time.empty() && (frame_time.back() == '\r' || frame_time.back() == ' ')) frame_time.pop_back();
  EXPECT_NE(r.out.find("Frame Time " + frame_time + ", " + std::to_string(channels) + " channels (CHANNELS)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("ticks/s"), std::string::npos) << "assimp's words: " << r.out;
}

TEST(ReduceTimes, KeysFileUsesTheExactRateAsResampleDoes) {
  // The walk with its Frame Time printed to 7 decimals, as most BVH files have it.
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_reduce_rate_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string text = test::slurp(kWalk);
  const std::size_t at = text.find("Frame Time:"), eol = text.find('\n', at);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, eol - at, "Frame Time: 0.0333333");
  std::ofstream(dir / "walk7.bvh", std::ios::binary) << text;
  const auto r = run_cli("reduce " + (dir / "walk7.bvh").string() + " -o " + (dir / "k.json").string() +
                         " --tolerance-deg 1 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::slurp(dir / "k.json"));
  fs::remove_all(dir);
  EXPECT_EQ(doc["frame_rate"], "30");
  EXPECT_EQ(doc["frame_time"].get<double>(), 1.0 / 30.0);
  // The last frame (always kept) at (frames − 1)/30 exactly, not (frames − 1)·0.0333333.
  const std::size_t frames = doc["frames"].get<std::size_t>();
  const auto& times = doc["joints"][0]["rotation"]["times"];
  EXPECT_EQ(times.back().get<double>(), static_cast<double>(frames - 1) / 30.0);
}

}  // namespace
}  // namespace rotinterp
