// No lost output: a run interrupted by SIGINT/SIGTERM while it writes leaves
// neither a partial output nor a temporary file, and exits with 128 + signal
// (README "Exit codes"). Each test starts a long run on a generated clip, waits
// until its temporary output file exists (so the signal lands during the write),
// signals it and inspects the output directory.
#include "support/processes.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

using test::exit_status;
using test::names_in;
using test::spawn;

// Polls `done` until it holds; a run that ends first is a failure.
bool wait_until(pid_t child, const std::function<bool()>& done, double seconds) {
  bool ended = false;
  const bool ok = test::wait_until(child, done, seconds, &ended);
  if (ended) ADD_FAILURE() << "the run ended before it started writing";
  return ok;
}

// A named temporary output of io/files/atomic_file.h: ".rotinterp.PID.N.tmp.EXT" (or a
// side file assimp made from it).
bool is_temp_name(const std::string& name) { return name.size() > 1 && name[0] == '.' && name.find(".tmp") != std::string::npos; }

// Whether `dir` holds a temporary file whose name ends with `suffix`.
bool has_temp(const fs::path& dir, const std::string& suffix = "") {
  for (const std::string& n : names_in(dir))
    if (is_temp_name(n) && n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
      return true;
  return false;
}

// A complete PNG ends with the IEND chunk.
bool complete_png(const fs::path& p) {
  const std::string bytes = test::slurp(p);
  static const std::string iend("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
  return bytes.size() > 20 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
         bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
}

class Interrupt : public ::testing::Test {
 protected:
  // One input for all tests: 20 s of a 31-joint walk at 120 Hz (2 401 frames).
  static void SetUpTestSuite() {
    in_dir_ = fs::temp_directory_path() / ("rotinterp_interrupt_in_" + std::to_string(::getpid()));
    fs::remove_all(in_dir_);
    fs::create_directories(in_dir_);
    const auto r = test::run_cli("synth " + clip().string() + " --kind walk --seconds 20 --fps 120 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(in_dir_); }
  static fs::path clip() { return in_dir_ / "walk.bvh"; }

  void SetUp() override {
    out_ = fs::temp_directory_path() / ("rotinterp_interrupt_out_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(out_);
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(out_); }

  // Runs `args`, signals it once it writes into `watched` (a named temporary file
  // ending with `suffix` shows up there, or, without a suffix, it has a file there
  // open: unnamed temporaries have no name), and returns its exit status; `delay`
  // later when given.
  int interrupt_while_writing(const std::vector<std::string>& args, const fs::path& watched, int sig,
                              std::chrono::milliseconds delay = std::chrono::milliseconds(0),
                              const std::string& suffix = "", int ignored = 0) {
    const pid_t pid = spawn(args, ignored);
    EXPECT_GT(pid, 0);
    const bool writing = wait_until(
        pid, [&] { return has_temp(watched, suffix) || (suffix.empty() && test::has_open_file_in(pid, watched)); }, 60.0);
    EXPECT_TRUE(writing) << "no temporary file appeared in " << watched;
    std::this_thread::sleep_for(delay);
    ::kill(pid, sig);
    return exit_status(pid);
  }

  static fs::path in_dir_;
  fs::path out_;
};

fs::path Interrupt::in_dir_;

TEST_F(Interrupt, SigintOrSighupDuringABvhWriteLeavesNoFileAndExits128PlusSignal) {
  // 2 401 frames at 120 Hz → 960 Hz: 19 201 frames, several MB of text.
  const fs::path target = out_ / "fast.bvh";
  for (int sig : {SIGINT, SIGHUP}) {
    const int status =
        interrupt_while_writing({"resample", clip().string(), "-o", target.string(), "--fps", "960", "-q"}, out_, sig);
    EXPECT_EQ(status, 128 + sig);
    EXPECT_EQ(names_in(out_), std::vector<std::string>{}) << "signal " << sig;
  }
}

TEST_F(Interrupt, AHangupIgnoredAsUnderNohupDoesNotStopTheRun) {
  const fs::path target = out_ / "fast.bvh";
  const int status = interrupt_while_writing(
      {"resample", clip().string(), "-o", target.string(), "--fps", "960", "-q"}, out_, SIGHUP,
      std::chrono::milliseconds(0), "", SIGHUP);
  EXPECT_EQ(status, 0);
  EXPECT_EQ(names_in(out_), std::vector<std::string>{"fast.bvh"});
  EXPECT_NE(test::slurp(target).find("Frames: 19201\n"), std::string::npos);
}

TEST_F(Interrupt, SigtermDuringAGltfExportLeavesNeitherGltfNorBuffer) {
  // The .bin buffer is written beside the temporary .gltf: the signal comes once
  // that buffer's temporary exists, and both must go.
  const fs::path target = out_ / "fast.gltf";
  const int status = interrupt_while_writing({"resample", clip().string(), "-o", target.string(), "--fps", "480", "-q"},
                                             out_, SIGTERM, std::chrono::milliseconds(0), ".bin");
  EXPECT_EQ(status, 128 + SIGTERM);
  EXPECT_EQ(names_in(out_), std::vector<std::string>{});
}

TEST_F(Interrupt, AnInterruptedRunKeepsTheOutputOfThePreviousRun) {
  // Overwriting an existing file: the old one stays whole until the new one is complete.
  const fs::path target = out_ / "kept.bvh";
  std::ofstream(target) << "previous output\n";
  const int status =
      interrupt_while_writing({"resample", clip().string(), "-o", target.string(), "--fps", "960", "-q"}, out_, SIGTERM);
  EXPECT_EQ(status, 128 + SIGTERM);
  EXPECT_EQ(names_in(out_), std::vector<std::string>{"kept.bvh"});
  EXPECT_EQ(test::slurp(target), "previous output\n");
}

TEST_F(Interrupt, SigtermDuringEvalLeavesNoCsvNorSummary) {
  // errors.csv is written through a temporary file from the start of the run;
  // the signal comes while the clip is being evaluated (bf at 24 subframes takes
  // seconds; the signal comes after 0.3 s).
  const fs::path dir = out_ / "eval";
  const int status = interrupt_while_writing({"eval", clip().string(), "--methods", "bf,squad", "--keep-every", "2,4,8",
                                              "--subframe", "24", "-j", "2", "-o", dir.string(), "-q"},
      dir, SIGTERM, std::chrono::milliseconds(300));
  EXPECT_EQ(status, 128 + SIGTERM);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{});
}

TEST_F(Interrupt, SigintDuringEvalIntoANewFolderRemovesTheFolderAndSaysSo) {
  // The run creates new/eval; interrupted, it takes both folders back and says one line.
  const fs::path parent = out_ / "new", dir = parent / "eval", err = out_ / "stderr.txt";
  const pid_t pid = spawn({"eval", clip().string(), "--methods", "bf,squad", "--keep-every", "2,4,8", "--subframe", "24",
                           "-j", "2", "-o", dir.string(), "-q"},
                          0, err.string());
  ASSERT_GT(pid, 0);
  EXPECT_TRUE(wait_until(pid, [&] { return test::has_open_file_in(pid, dir); }, 60.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 128 + SIGINT);
  EXPECT_FALSE(fs::exists(parent)) << "the folders the run created stay behind";
  EXPECT_EQ(test::slurp(err), "rotinterp: interrupted\n");
}

TEST_F(Interrupt, SigintDuringEvalIntoAFolderWithEarlierOutputsKeepsThem) {
  const fs::path dir = out_ / "eval";
  ASSERT_EQ(test::run_cli("eval " + clip().string() + " --methods slerp --keep-every 4 --no-plots -q -o " + dir.string())
                .exit_code,
            0);
  const std::vector<std::string> earlier = names_in(dir);
  ASSERT_FALSE(earlier.empty());
  const std::string csv = test::slurp(dir / "errors.csv");
  const int status = interrupt_while_writing({"eval", clip().string(), "--methods", "bf,squad", "--keep-every", "2,4,8",
                                              "--subframe", "24", "-j", "2", "-o", dir.string(), "-q"},
                                             dir, SIGINT, std::chrono::milliseconds(300));
  EXPECT_EQ(status, 128 + SIGINT);
  EXPECT_EQ(names_in(dir), earlier);
  EXPECT_EQ(test::slurp(dir / "errors.csv"), csv);
}

TEST_F(Interrupt, SigintDuringRenderLeavesOnlyCompleteFrames) {
  if (test::run_cli("render --help").exit_code != 0) GTEST_SKIP() << "built without the renderer";
  // Frames are committed one by one: those done stay, each complete; no temporary file.
  const fs::path dir = out_ / "render";
  fs::create_directories(dir);
  const int status = interrupt_while_writing({"render", clip().string(), "-o", dir.string(), "--methods", "slerp,squad",
                                              "--frames", "0:2400:4", "--size", "320x180", "-q"},
                                             dir, SIGINT);
  EXPECT_EQ(status, 128 + SIGINT);
  std::size_t frames = 0;
  for (const std::string& n : names_in(dir)) {
    EXPECT_FALSE(is_temp_name(n)) << n;
    EXPECT_TRUE(complete_png(dir / n)) << n;
    ++frames;
  }
  EXPECT_LT(frames, 601u) << "the run finished before the signal";
}

}  // namespace
}  // namespace rotinterp
