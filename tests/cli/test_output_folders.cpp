// Output folders: every command creates the missing folders of its output, a trailing
// '/' makes -o a folder, and a failed run takes back the folders it created.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

class OutputFolders : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_output_folders_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const auto r = run_cli("synth " + clip() + " --kind walk --seconds 1 --fps 30 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string clip() const { return (dir_ / "walk.bvh").string(); }
  fs::path dir_;
};

TEST_F(OutputFolders, EveryCommandCreatesTheMissingFoldersOfItsOutput) {
  for (const std::string& args :
       {"resample " + clip() + " --fps 60 -q -o " + (dir_ / "r/a/out.bvh").string(),
        "reduce " + clip() + " --tolerance 1deg -q -o " + (dir_ / "d/a/keys.json").string(),
        "synth " + (dir_ / "s/a/new.bvh").string() + " -q",
        "eval " + clip() + " --methods slerp --keep-every 4 --no-plots -q -o " + (dir_ / "e/a").string()}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
  }
  EXPECT_TRUE(fs::is_regular_file(dir_ / "r/a/out.bvh"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "d/a/keys.json"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "s/a/new.bvh"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "e/a/errors.csv"));
}

TEST_F(OutputFolders, ATrailingSlashMakesTheOutputAFolderNamedAsAFolderRunNamesIt) {
  const fs::path single = dir_ / "deep3/a/", folder_run = dir_ / "run";
  const auto r = run_cli("resample " + clip() + " --fps 60 -q -o " + single.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(run_cli("resample " + clip() + " --fps 60 -q --format bvh -o " + folder_run.string()).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "deep3/a/walk.bvh"));
  EXPECT_TRUE(fs::is_regular_file(folder_run / "walk.bvh"));
}

TEST_F(OutputFolders, AFailedRunRemovesTheFoldersItCreated) {
  std::ofstream(dir_ / "notes.txt") << "not a motion clip\n";
  const auto r = run_cli("resample " + (dir_ / "notes.txt").string() + " --fps 60 -q -o " + (dir_ / "new/a/out.bvh").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "new")) << r.err;
  // A folder that was there before stays.
  fs::create_directories(dir_ / "old");
  run_cli("resample " + (dir_ / "notes.txt").string() + " --fps 60 -q -o " + (dir_ / "old/b/out.bvh").string());
  EXPECT_TRUE(fs::is_directory(dir_ / "old"));
  EXPECT_FALSE(fs::exists(dir_ / "old/b"));
}

}  // namespace
}  // namespace rotinterp
