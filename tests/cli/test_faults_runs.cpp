// Runs that end early or badly (README "Robustness"): an eval output directory is
// written by one run at a time and as a unit; a killed run leaves nothing; long
// names work; out of memory and numbers out of range are one line.
#include "faults.h"

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using namespace test;

TEST_F(Faults, ASecondEvalIntoADirectoryInUseIsRefusedWithOneLine) {
  const fs::path e = out_ / "e";
  fs::create_directories(e);
  // Another run holds the directory (as eval does while it writes).
  const int fd = ::open(e.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);
  const auto r = run_cli("eval " + clip().string() + " --methods slerp --keep-every 4 -q -o " + e.string());
  ::close(fd);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("another rotinterp run is writing to this directory"), std::string::npos) << r.err;
  EXPECT_EQ(names_in(e), std::vector<std::string>{});
}

TEST_F(Faults, ASignalWhileEvalDrawsItsPlotsLeavesAllOfOneRunNeverAMix) {
  // While the plots are drawn the run holds errors.csv, summary.json, clips.csv and
  // a plot open (unnamed) in DIR: SIGTERM then. The directory must hold the previous
  // run's nine files, or (a signal held back during the final renames) this run's
  // nine, never new CSV/JSON beside old plots.
  const fs::path e = out_ / "e";
  const std::vector<std::string> args = {"eval", clip().string(), "--methods", "slerp,squad,c2,nlerp,expmap",
                                         "--keep-every", "2,3,4,6,8", "-j", "1", "-q", "-o", e.string()};
  const std::vector<std::string> files = {"clip_errors.png", "clip_errors.svg", "clips.csv", "error_vs_spacing.png", "error_vs_spacing.svg",
                                          "errors.csv", "summary.json", "worst_clip_joints.png", "worst_clip_joints.svg"};
  int caught = 0;
  for (int round = 0; round < 5; ++round) {
    fs::create_directories(e);
    for (const std::string& n : files) write_text(e / n, "previous " + n + "\n");
    const pid_t pid = test::spawn(args);
    // (A named temporary plot, ".*.png", is the same moment for a writer without unnamed ones.)
    const auto plotting = [&] {
      for (const std::string& n : names_in(e))
        if (n[0] == '.' && n.size() > 4 && n.compare(n.size() - 4, 4, ".png") == 0) return true;
      return test::open_files_in(pid, e) >= 4;
    };
    const bool drawing = test::wait_until(pid, plotting, 60.0);
    ::kill(pid, SIGTERM);
    const int status = test::exit_status(pid);
    if (!drawing) continue;  // it finished between two polls
    ++caught;
    EXPECT_EQ(status, 128 + SIGTERM);
    EXPECT_EQ(names_in(e), files);
    int previous = 0;
    for (const std::string& n : files) previous += slurp(e / n) == "previous " + n + "\n";
    EXPECT_TRUE(previous == 0 || previous == 9) << previous << " of 9 files are the previous run's";
  }
  EXPECT_GT(caught, 0) << "the signal never came while the plots were drawn";
}

TEST_F(Faults, AnEvalWithoutPlotsLeavesNoPlotOfAnEarlierRunBesideItsFiles) {
  const fs::path e = out_ / "e";
  const std::string args = "eval " + clip().string() + " --methods slerp --keep-every 4 -q -o " + e.string();
  ASSERT_EQ(run_cli(args).exit_code, 0);
  ASSERT_TRUE(fs::exists(e / "error_vs_spacing.png"));
  ASSERT_EQ(run_cli(args + " --no-plots").exit_code, 0);
  EXPECT_EQ(names_in(e), (std::vector<std::string>{"clips.csv", "errors.csv", "summary.json"}));
}

TEST_F(Faults, AKilledRunLeavesNoTemporaryFile) {
  // SIGKILL while the output is being written (the run has a file in the output
  // directory open): nothing may be left, for our writer and for eval's outputs.
  const std::string big = (in_ / "big.bvh").string();
  ASSERT_EQ(run_cli("synth " + big + " --kind walk --seconds 30 --fps 120 -q").exit_code, 0);
  const std::vector<std::vector<std::string>> runs = {
      {"resample", big, "-o", (out_ / "x.bvh").string(), "--fps", "480", "-q"},
      {"eval", big, "--methods", "slerp,squad", "--keep-every", "2", "-j", "1", "-q", "-o", (out_ / "e").string()}};
  for (const auto& args : runs) {
    const pid_t pid = test::spawn(args);
    const fs::path watched = args[0] == "eval" ? out_ / "e" : out_;
    EXPECT_TRUE(test::wait_until(pid, [&] { return test::has_open_file_in(pid, watched); }, 60.0)) << args[0];
    ::kill(pid, SIGKILL);
    EXPECT_EQ(test::exit_status(pid), 1000 + SIGKILL);
    std::vector<std::string> left;
    for (const auto& e : fs::recursive_directory_iterator(out_)) left.push_back(e.path().filename().string());
    EXPECT_TRUE(left.empty() || left == std::vector<std::string>{"e"}) << args[0] << " left " << left.front();
  }
}

TEST_F(Faults, StaleTemporariesOfDeadRunsAreRemovedAndLiveOnesKept) {
  // A PID no process can have (above the kernel's pid_max): a reaped child's PID
  // could be reused meanwhile on a busy machine.
  long pid_max = 0;
  std::ifstream("/proc/sys/kernel/pid_max") >> pid_max;
  ASSERT_GT(pid_max, 0);
  const long dead = pid_max + 1;
  const std::string stale = ".rotinterp." + std::to_string(dead) + ".0.tmp.bvh";
  const std::string fresh = ".rotinterp." + std::to_string(dead) + ".1.tmp.bvh";
  const std::string alive = ".rotinterp." + std::to_string(::getpid()) + ".0.tmp.bvh";
  for (const std::string& n : {stale, fresh, alive}) write_text(out_ / n, "left by a killed run\n");
  const struct utimbuf hour_ago{std::time(nullptr) - 3600, std::time(nullptr) - 3600};
  ::utime((out_ / stale).c_str(), &hour_ago);
  ::utime((out_ / alive).c_str(), &hour_ago);
  const auto r = run_cli("resample " + clip().string() + " -o " + (out_ / "x.bvh").string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> kept = {alive, fresh, "x.bvh"};
  std::sort(kept.begin(), kept.end());  // as names_in lists them (the PIDs' digits decide the order)
  EXPECT_EQ(names_in(out_), kept);
}

TEST_F(Faults, TheAssimpChildDiesWithItsParent) {
  // A non-BVH input is imported in a child process; killing the parent must not
  // leave it running (it used to go on for seconds).
  const fs::path fbx = in_ / "long.fbx";
  ASSERT_EQ(run_cli("synth " + fbx.string() + " --kind walk --seconds 60 --fps 120 -q").exit_code, 0);
  const pid_t pid = test::spawn({"info", fbx.string()});
  pid_t child = 0;
  const auto find_child = [&] {
    std::ifstream f("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
    return static_cast<bool>(f >> child);
  };
  ASSERT_TRUE(test::wait_until(pid, find_child, 30.0)) << "no import child appeared";
  ::kill(pid, SIGKILL);
  EXPECT_EQ(test::exit_status(pid), 1000 + SIGKILL);
  // The child is re-parented and reaped by init (or a subreaper): wait until it is gone.
  const auto gone = [&] { return ::kill(child, 0) != 0 || slurp("/proc/" + std::to_string(child) + "/stat").find(") Z") != std::string::npos; };
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  while (!gone() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(gone()) << "the assimp child " << child << " outlived its parent";
}

TEST_F(Faults, TargetNamesOfUpTo255BytesCanBeWritten) {
  for (const char* ext : {".bvh", ".fbx"}) {
    const std::string name = std::string(255 - std::strlen(ext), 'n') + ext;
    const auto r = run_cli("resample " + clip().string() + " -o " + (out_ / name).string() + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out_ / name));
  }
  const std::string spec_base = std::string(255 - std::strlen(".bvh.synth"), 's') + ".bvh";
  const auto r = run_cli("synth " + (out_ / spec_base).string() + " -q");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(Faults, OutOfMemoryIsOneLineExit1AndLeavesNothing) {
#ifdef ROTINTERP_SANITIZED
  GTEST_SKIP() << "a sanitizer build cannot run under an address-space limit (shadow memory)";
#endif
  // 600 MB of address space; resample to 10⁸ keys (≈ 4 GB, just under its limit)
  // needs far more, on the main thread and on the workers (which of them fails
  // first varies from run to run).
  const std::string big = (in_ / "ten_seconds.bvh").string();
  ASSERT_EQ(run_cli("synth " + big + " --kind walk --seconds 10 --fps 120 -q").exit_code, 0);
  for (int run = 0; run < 3; ++run) {
    const std::string args = "resample " + big + " -o " + (out_ / "x.bvh").string() + " --fps 320000 -q";
    const std::string cmd = "ulimit -v 600000; exec " + std::string(ROTINTERP_CLI) + " " + args + " 2>" +
                            (in_ / "err").string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << args << ": killed by signal " << WTERMSIG(status);
    const std::string err = slurp(in_ / "err");
    EXPECT_EQ(WEXITSTATUS(status), 1) << args << "\n" << err;
    EXPECT_EQ(err, "rotinterp: " + big + ": out of memory\n") << args;
    std::vector<std::string> left;
    for (const auto& f : fs::recursive_directory_iterator(out_)) left.push_back(f.path().filename().string());
    EXPECT_TRUE(left.empty()) << args << " left " << left.front();
  }
}

TEST_F(Faults, NumbersOutOfRangeAreCalledThatNotNotANumber) {
  const std::string io = "resample " + clip().string() + " -o " + (out_ / "x.bvh").string() + " ";
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases = {
      {io + "--fps -30", "--fps '-30' must be greater than 0"},
      {io + "--fps 1e10", "--fps '1e10' is out of range (at most 1e9 Hz)"},
      {io + "--keep-every 1e12", "--keep-every '1e12' is too large"},
      {io + "--keep-every 2.5", "--keep-every '2.5' is not a whole number"},
      {io + "--keep-every -3", "--keep-every '-3' is too small"},
      {"synth " + (out_ / "s.bvh").string() + " --fps -30", "--fps '-30' must be greater than 0"},
      {"eval " + clip().string() + " -o " + (out_ / "e").string() + " --keep-every 2,1e12", "--keep-every '1e12' is too large"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.find("not a number"), std::string::npos) << r.err;
  }
  // 1e9 Hz in exponent form is read as the rate it is; what is wrong is the key count.
  const auto r = run_cli(io + "--fps 1e9");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("more than"), std::string::npos) << r.err;
  if (render_built()) {
    const auto rr = run_cli("render " + clip().string() + " -o " + (out_ / "p").string() + " --keep-every 1e12");
    EXPECT_EQ(rr.exit_code, 2) << rr.err;
    EXPECT_NE(rr.err.find("--keep-every '1e12' is too large"), std::string::npos) << rr.err;
  }
}

}  // namespace
}  // namespace rotinterp
