// Every long job's progress line: one format (done/total, rate, ETA) on a terminal,
// nothing with --quiet or when stderr is not a terminal.
#include "progress_line.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace rotinterp::cli {
namespace {

namespace fs = std::filesystem;

TEST(Progress, TheLineGivesDoneTotalRateAndEta) {
  EXPECT_EQ(progress_line("eval", "clips", 3, 12, 2.0), "eval  3/12 clips (25%)  1.5 clips/s  ETA 6s");
  EXPECT_EQ(progress_line("render", "frames", 600, 1200, 60.0), "render  600/1200 frames (50%)  10 frames/s  ETA 1m00s");
  EXPECT_EQ(progress_line("resample", "", 0, 31, 0.5), "resample  0/31 (0%)  0/s  ETA ?");
}

// The command's terminal output, run under `script` (a pseudo-terminal).
std::string on_a_terminal(const std::string& args) {
  const std::string cmd = "script -qec \"" + std::string(ROTINTERP_CLI) + " " + args + "\" /dev/null 2>&1";
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    ::pclose(p);
  }
  return out;
}

TEST(Progress, EvalShowsTheSameLineOnATerminalAndNoneWhenQuietOrPiped) {
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_progress_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string clip = (dir / "walk.bvh").string();
  ASSERT_EQ(test::run_cli("synth " + clip + " --kind walk --seconds 1 --fps 30 -q").exit_code, 0);
  const std::string eval = "eval " + clip + " --methods slerp --keep-every 4 --no-plots -o " + (dir / "e").string();
  const std::string shown = on_a_terminal(eval);
  EXPECT_NE(shown.find("eval  1/1 clips (100%)  "), std::string::npos) << shown;
  EXPECT_NE(shown.find(" clips/s  ETA 0s"), std::string::npos) << shown;
  EXPECT_EQ(on_a_terminal(eval + " -q").find("ETA"), std::string::npos);
  EXPECT_EQ(test::run_cli(eval).err.find("ETA"), std::string::npos) << "stderr is no terminal";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::cli
