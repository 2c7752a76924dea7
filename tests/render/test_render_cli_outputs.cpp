// render's outputs where the user meant them (issue 28): -o is a directory, and a
// name that reads as a file, or an existing file, is refused with why; --video-fps 0
// is refused like -5; frames that are all keys are warned about.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

const std::string kWalk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";

class RenderOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_render_outputs_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  static std::string small() { return " -m slerp --size 160x90 --backend osmesa -q"; }
  fs::path dir_;
};

TEST_F(RenderOutputs, AnOutputDirectoryNamedLikeAFileIsRefusedAndNotCreated) {
  for (const char* name : {"out.png", "clip.MP4", "walk50.bvh"}) {
    const auto r = run_cli("render " + kWalk + " -o " + path(name) + " --frames 10" + small());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.err;
    EXPECT_NE(r.err.find("looks like a file name"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("see 'rotinterp render --help'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path(name))) << name;
  }
}

TEST_F(RenderOutputs, AnExistingFileAsTheOutputDirectoryIsCalledThat) {
  std::ofstream(path("walk50")) << "not a directory\n";
  const auto r = run_cli("render " + kWalk + " -o " + path("walk50") + " --frames 10" + small());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("'" + path("walk50") + "' is an existing file"), std::string::npos) << r.err;
}

TEST_F(RenderOutputs, VideoFpsZeroIsRefusedLikeANegativeRate) {
  for (const char* fps : {"0", "-5"}) {
    const auto r = run_cli("render " + kWalk + " --video " + path("v.mp4") + " --video-fps " + fps + small());
    EXPECT_EQ(r.exit_code, 2) << fps << "\n" << r.err;
    EXPECT_NE(r.err.find(std::string("--video-fps ") + fps + " must be within (0, 1000]"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("v.mp4")));
  }
}

TEST_F(RenderOutputs, FramesThatAreAllKeysAreWarnedAboutWithWhatToDo) {
  const auto keys = run_cli("render " + kWalk + " -o " + path("k") + " --frames 50:70:20 --keep-every 10" + small());
  EXPECT_EQ(keys.exit_code, 0) << keys.err;
  EXPECT_NE(keys.err.find("warning: every frame drawn is a key frame (--keep-every 10 keeps frames 0, 10, 20, …)"),
            std::string::npos)
      << keys.err;
  EXPECT_NE(keys.err.find("--frames 55:75:20"), std::string::npos) << keys.err;
  const auto between = run_cli("render " + kWalk + " -o " + path("b") + " --frames 55:75:20 --keep-every 10" + small());
  EXPECT_EQ(between.exit_code, 0) << between.err;
  EXPECT_EQ(between.err, "") << "frames between keys: no warning";
}

}  // namespace
}  // namespace rotinterp::render
