// `rotinterp resample` and `rotinterp synth` from the outside: outputs, summary
// lines, and every error case with its exit code and no output file left behind.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using rotinterp::test::run_cli;
namespace fs = std::filesystem;

namespace {

class ResampleCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_resample_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // A 2 s synth walk at 30 Hz.
  std::string walk() {
    const std::string p = path("walk.bvh");
    if (!fs::exists(p)) {
      const auto r = run_cli("synth " + p + " --kind walk --seconds 2 --fps 30 --seed 3");
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    return p;
  }
  fs::path dir_;
};

struct ErrorCase {
  std::string args;    // after "resample "
  std::string needle;  // expected in the one stderr line
};

// Each case fails with `code`, one line on stderr containing its needle, and no `out`.
void expect_errors(const std::vector<ErrorCase>& cases, int code, const std::string& out) {
  for (const ErrorCase& c : cases) {
    const auto r = run_cli("resample " + c.args);
    EXPECT_EQ(r.exit_code, code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

std::string frames_line(const std::string& bvh) {
  const std::string text = rotinterp::test::slurp(bvh);
  const std::size_t at = text.find("Frames:");
  return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

}  // namespace

TEST_F(ResampleCli, SynthWritesABvhWithItsSpecAndASummary) {
  const auto r = run_cli("synth " + path("c.bvh") + " --kind constant --seconds 1 --fps 50 --seed 9 --joints 5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("c.bvh")));
  EXPECT_EQ(frames_line(path("c.bvh")), "Frames: 51");
  EXPECT_EQ(rotinterp::test::slurp(path("c.bvh.synth")), "kind=constant seconds=1 fps=50 seed=9 joints=5\n");
  EXPECT_NE(r.out.find("51 frames × 5 joints"), std::string::npos) << r.out;
}

TEST_F(ResampleCli, ResampleWritesTheRequestedRateAndOneSummaryLine) {
  const std::string in = walk(), out = path("out50.bvh");
  const auto r = run_cli("resample " + in + " -o " + out + " --fps 50");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frames_line(out), "Frames: 101");  // 2 s · 50 + 1
  EXPECT_NE(rotinterp::test::slurp(out).find("Frame Time: 0.02"), std::string::npos);
  EXPECT_NE(r.out.find("61 → 101 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("30 Hz → 50 Hz"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // no progress when stderr is not a terminal
}

TEST_F(ResampleCli, KeepEveryRangeAndOverridesWork) {
  const std::string in = walk();
  auto r = run_cli("resample " + in + " -o " + path("k.bvh") + " --keep-every 4 --method-for Head=slerp --translation linear");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(frames_line(path("k.bvh")), "Frames: 61");
  r = run_cli("resample " + in + " -o " + path("r.bvh") + " --fps 30000/1001 --range 0.5:1.5 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(frames_line(path("r.bvh")), "Frames: 30");  // floor(1 s · 29.97) + 1
}

TEST_F(ResampleCli, UsageErrorsExitTwoWithOneLineAndNoOutput) {
  const std::string in = walk(), out = path("never.bvh"), io = in + " -o " + out + " ";
  expect_errors({{io + "--fps 0", "greater than 0"},
                 {io + "--fps -30", "--fps '-30' must be greater than 0"},
                 {io + "--fps abc", "not a number"},
                 {io + "--fps 30 --keep-every 2", "not both"},
                 {io + "--keep-every 0", "--keep-every '0' is too small"},
                 {io + "--keep-every two", "--keep-every 'two' is not a number"},
                 {io + "--method cubic-ish", "valid: "},
                 {io + "--method-for Head", "JOINT=METHOD"},
                 {io + "--method-for Head=nope", "unknown method 'nope'"},
                 {io + "--translation spline", "linear, cubic"},
                 {io + "--range 3", "START:END"},
                 {io + "--range 2:1", "after START"},
                 {io + "--bvh-order XYY", "permutation"}},
                2, out);
  const auto r = run_cli("resample " + in + " -o " + path("x.txt"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown format"), std::string::npos) << r.err;
}

TEST_F(ResampleCli, InputProblemsExitOneWithOneLineAndNoOutput) {
  const std::string in = walk(), out = path("never.bvh");
  expect_errors({{path("missing.bvh") + " -o " + out, "missing.bvh"},
                 {in + " -o " + out + " --range 1:5", "runs past the clip's end"},
                 {in + " -o " + out + " --method-for Tail=slerp", "no joint 'Tail'"}},
                1, out);
  // A folder that cannot be made (a plain file has its name): one line, nothing written.
  std::ofstream(path("blocker")) << "a file where a folder would go\n";
  const std::string unwritable = path("blocker/dir/out.bvh");
  const auto r = run_cli("resample " + in + " -o " + unwritable);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(path("blocker") + ": cannot create the output folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(unwritable));
}

TEST_F(ResampleCli, SynthRejectsBadOptions) {
  for (const std::string& args : {std::string("--kind dance"), std::string("--seconds 0"), std::string("--seconds x"),
                                  std::string("--fps 0"), std::string("--seed -1"), std::string("--joints 0")}) {
    const auto r = run_cli("synth " + path("s.bvh") + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("s.bvh"))) << args;
  }
}
