// Every command that runs over a folder runs on the one folder-run facility
// (batch/folder_run.h): a bad file among good ones is said by the same line and ends
// with the same exit code in resample, eval and info --summary, and the good files
// are still done.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

constexpr int kExitPartial = 3;  // README "Exit codes"

class FolderRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_folder_runs_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in");
    for (int i = 0; i < 2; ++i) {
      const auto r = run_cli("synth " + (dir_ / "in" / ("walk" + std::to_string(i) + ".bvh")).string() +
                             " --kind walk --seconds 1 --fps 30 --seed " + std::to_string(i + 1));
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    bad_ = (dir_ / "in" / "broken.bvh").string();
    std::ofstream(bad_) << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The lines of `err` that name the bad file.
  std::vector<std::string> lines_naming_bad(const std::string& err) const {
    std::vector<std::string> found;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);)
      if (line.find(bad_) != std::string::npos) found.push_back(line);
    return found;
  }

  fs::path dir_;
  std::string bad_;
};

TEST_F(FolderRuns, ABadFileIsOneLineAndExitThreeInResampleEvalAndInfo) {
  const std::string in = (dir_ / "in").string();
  const auto resample = run_cli("resample " + in + " -o " + (dir_ / "resampled").string() + " --keep-every 2 -q -j 2");
  const auto eval = run_cli("eval " + in + " -o " + (dir_ / "eval").string() + " -m slerp --no-plots -q -j 2");
  const auto info = run_cli("info " + in + " --summary -j 2");
  for (const auto* r : {&resample, &eval, &info}) {
    EXPECT_EQ(r->exit_code, kExitPartial) << r->err;
    ASSERT_EQ(lines_naming_bad(r->err).size(), 1u) << r->err;
    EXPECT_EQ(lines_naming_bad(r->err)[0].rfind("rotinterp: " + bad_ + ": ", 0), 0u) << r->err;
  }
  // The same line, word for word: one reader, one way of saying a failed file.
  EXPECT_EQ(lines_naming_bad(resample.err), lines_naming_bad(eval.err));
  EXPECT_EQ(lines_naming_bad(resample.err), lines_naming_bad(info.err));
  // The good files are done all the same.
  EXPECT_TRUE(fs::is_regular_file(dir_ / "resampled" / "walk0.bvh"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "resampled" / "walk1.bvh"));
  EXPECT_FALSE(fs::exists(dir_ / "resampled" / "broken.bvh"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "eval" / "errors.csv"));
  EXPECT_NE(info.out.find("walk1.bvh"), std::string::npos);
}

TEST_F(FolderRuns, ShardsOfResampleAndEvalTakeTheSameFiles) {
  const std::string in = (dir_ / "in").string();
  fs::remove(bad_);
  // Shard 2/2 of the two clips found (sorted) is the second, walk1.bvh, in both commands.
  const auto resample = run_cli("resample " + in + " -o " + (dir_ / "resampled").string() + " --shard 2/2 -q");
  ASSERT_EQ(resample.exit_code, 0) << resample.err;
  EXPECT_FALSE(fs::exists(dir_ / "resampled" / "walk0.bvh"));
  EXPECT_TRUE(fs::exists(dir_ / "resampled" / "walk1.bvh"));
  const auto eval = run_cli("eval " + in + " -o " + (dir_ / "eval").string() + " -m slerp --no-plots -q --shard 2/2");
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  const std::string csv = test::slurp(dir_ / "eval" / "errors.csv");
  EXPECT_EQ(csv.find("walk0.bvh"), std::string::npos);
  EXPECT_NE(csv.find("walk1.bvh"), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
