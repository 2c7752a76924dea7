// Nothing lost under faults (README "Robustness"): a write that fails anywhere in
// any writer (a full disk) exits 1 and keeps the previous file; an output that is
// an input is refused; replaced files keep their mode and owner; an eval output
// directory is written as a unit, by one run at a time; a killed run leaves
// nothing; long names work; out of memory is one line.
#include "support/processes.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <utime.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::names_in;
using test::run_cli;
using test::slurp;

// The output directory's files and their bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const std::string& n : names_in(dir)) files[n] = slurp(dir / n);
  return files;
}

// "name (N bytes), …": what a snapshot holds, short enough for a failure message.
std::string describe(const std::map<std::string, std::string>& files) {
  std::string out;
  for (const auto& [name, bytes] : files)
    out += (out.empty() ? "" : ", ") + name + " (" + std::to_string(bytes.size()) + " bytes)";
  return out;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Every file in `dir` replaced by a marker naming it: a failed run must leave these.
void mark_previous(const fs::path& dir) {
  for (const std::string& n : names_in(dir)) write_text(dir / n, "previous " + n + "\n");
}

bool render_built() { return run_cli("render --help").exit_code == 0; }

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// Runs the CLI with the checked-operation fault seam of io/atomic_file.h set.
test::CliResult run_with_fault(const std::string& args, long at) {
  ::setenv("ROTINTERP_TEST_FAULT_AT", std::to_string(at).c_str(), 1);
  auto r = run_cli(args);
  ::unsetenv("ROTINTERP_TEST_FAULT_AT");
  return r;
}

class Faults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    in_ = fs::temp_directory_path() / ("rotinterp_faults_in_" + std::to_string(::getpid()));
    fs::remove_all(in_);
    fs::create_directories(in_);
    // 2 s of a 31-joint walk at 120 Hz: a 110 kB BVH, several writes per output.
    const auto r = run_cli("synth " + clip().string() + " --kind walk --seconds 2 --fps 120 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(in_); }
  static fs::path clip() { return in_ / "walk.bvh"; }

  void SetUp() override {
    out_ = fs::temp_directory_path() / ("rotinterp_faults_out_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(out_);
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(out_); }

  // Runs `args` (writing into `dir`) once to get its outputs, marks them, then
  // makes the 1st, 2nd, … checked operation fail until a run gets through: each
  // failing run must exit 1 with one line and leave the marked files as they were
  // (`unit`; else, as render does, each file either marked or replaced whole) and
  // nothing else. Returns how many fault points the writer has.
  static int fail_everywhere(const std::string& args, const fs::path& dir, bool unit = true) {
    const auto good = run_cli(args);
    EXPECT_EQ(good.exit_code, 0) << args << "\n" << good.err;
    mark_previous(dir);
    const auto previous = snapshot(dir);
    EXPECT_FALSE(previous.empty()) << args;
    for (long at = 1; at < 400; ++at) {
      const auto r = run_with_fault(args, at);
      if (r.exit_code == 0) return static_cast<int>(at - 1);
      EXPECT_EQ(r.exit_code, 1) << args << " fault at " << at << "\n" << r.err;
      EXPECT_EQ(lines(r.err), 1) << args << " fault at " << at << "\n" << r.err;
      EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << args << " fault at " << at << "\n" << r.err;
      const auto now = snapshot(dir);
      if (unit) {
        EXPECT_TRUE(now == previous) << args << " fault at " << at << ": the previous output changed: " << describe(now);
      } else {
        EXPECT_EQ(names_in(dir).size(), previous.size()) << args << " fault at " << at << ": files left";
        for (const auto& [name, bytes] : now)
          EXPECT_TRUE(bytes == previous.at(name) || bytes.compare(0, 4, "\x89PNG") == 0) << name;
      }
      for (const auto& [name, bytes] : now) EXPECT_EQ(previous.count(name), 1u) << args << " left " << name;
    }
    ADD_FAILURE() << args << ": never got through";
    return 0;
  }

  static fs::path in_;
  fs::path out_;
};

fs::path Faults::in_;

TEST_F(Faults, AWriteFailingAtAnyPointOfResampleKeepsThePreviousFileAndExits1) {
  // BVH is ours; FBX, Collada, glTF (+ .bin) and GLB go through assimp's exporters.
  for (const char* ext : {".bvh", ".fbx", ".dae", ".gltf", ".glb"}) {
    const fs::path dir = out_ / (std::string("r") + (ext + 1));
    fs::create_directories(dir);
    const int points =
        fail_everywhere("resample " + clip().string() + " -o " + (dir / (std::string("x") + ext)).string() + " -q", dir);
    EXPECT_GE(points, 2) << ext << ": every write and the sync are checked";
  }
}

TEST_F(Faults, AWriteFailingAtAnyPointOfSynthKeepsTheClipAndItsSpec) {
  const int points = fail_everywhere("synth " + (out_ / "s.bvh").string() + " --seconds 4 --fps 60 -q", out_);
  EXPECT_GE(points, 3);
}

TEST_F(Faults, AWriteFailingAtAnyPointOfEvalKeepsTheWholePreviousRun) {
  // errors.csv, summary.json and both PNG plots are one unit: a failure while the
  // plots are encoded leaves the previous CSV and JSON too.
  const fs::path dir = out_ / "e";
  const int points = fail_everywhere(
      "eval " + clip().string() + " --methods slerp,squad --keep-every 2,4 -j 1 -q -o " + dir.string(), dir);
  EXPECT_GE(points, 8) << "CSV, JSON and two PNGs, each written and synced";
}

TEST_F(Faults, AWriteFailingAtAnyPointOfRenderLeavesOnlyWholeFrames) {
  if (!render_built()) GTEST_SKIP() << "built without the renderer";
  const fs::path dir = out_ / "png";
  const int points = fail_everywhere("render " + clip().string() + " -o " + dir.string() +
                                         " --methods slerp --frames 0:2:1 --size 160x120 --sheet -q",
                                     dir, false);
  EXPECT_GE(points, 4);
}

// A 1 MiB tmpfs is a real full disk (root only: CI runs as root).
class FullDisk : public Faults {
 protected:
  void SetUp() override {
    Faults::SetUp();
    disk_ = out_ / "m";
    fs::create_directories(disk_);
    if (::mount("tmpfs", disk_.c_str(), "tmpfs", 0, "size=1m") != 0)
      GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "): needs root, as in CI";
    mounted_ = true;
  }
  void TearDown() override {
    if (mounted_) ::umount2(disk_.c_str(), MNT_DETACH);
    Faults::TearDown();
  }
  // Fills the disk but `free_bytes` (roughly: tmpfs counts whole pages).
  void fill_leaving(std::size_t free_bytes) {
    const fs::path filler = disk_ / "filler";
    fs::remove(filler);
    const std::size_t size = (std::size_t{1} << 20) - std::min<std::size_t>(free_bytes, std::size_t{1} << 20);
    write_text(filler, std::string(size, 'f'));  // as much as fits
  }
  fs::path disk_;
  bool mounted_ = false;
};

TEST_F(FullDisk, EveryWriterFailsCleanlyOnAFullDisk) {
  const std::string big = (in_ / "big.bvh").string();  // 1.6 MB of BVH: never fits
  ASSERT_EQ(run_cli("synth " + big + " --kind walk --seconds 12 --fps 120 -q").exit_code, 0);
  struct Writer {
    std::string args;
    fs::path dir;
    std::vector<std::string> outputs;  // what it writes into dir
    bool unit = true;                  // all or nothing (render keeps whole frames)
  };
  const fs::path w = disk_ / "w", e = disk_ / "e", p = disk_ / "p";
  std::vector<Writer> writers;
  for (const std::string ext : {"bvh", "fbx", "dae", "gltf", "glb"})
    writers.push_back({"resample " + big + " -o " + (w / ("x." + ext)).string() + " -q", w, {"x." + ext}});
  writers[3].outputs.push_back("x.bin");  // the .gltf's buffer
  writers.push_back({"synth " + (w / "s.bvh").string() + " --seconds 30 --fps 120 -q", w, {"s.bvh", "s.bvh.synth"}});
  writers.push_back({"eval " + clip().string() + " --methods slerp,squad --keep-every 2,4 -j 1 -q -o " + e.string(), e,
                     {"errors.csv", "clips.csv", "summary.json", "error_vs_spacing.png", "error_vs_spacing.svg",
                      "worst_clip_joints.png", "worst_clip_joints.svg", "clip_errors.png", "clip_errors.svg"}});
  if (render_built())
    writers.push_back({"render " + clip().string() + " -o " + p.string() +
                           " --methods slerp,squad --frames 0:1:1 --size 1920x1080 -q",
                       p, {"frame_000000.png", "frame_000001.png"}, false});
  for (const Writer& wr : writers) {
    fs::create_directories(wr.dir);
    for (const std::string& n : wr.outputs) write_text(wr.dir / n, "previous " + n + "\n");
    const auto previous = snapshot(wr.dir);
    // From nothing free to half the disk, the run fails at another point each time.
    int failed = 0;
    for (std::size_t free_kib : {0, 4, 16, 64, 192, 512}) {
      fill_leaving(free_kib << 10);
      const auto r = run_cli(wr.args);
      const std::string what = wr.args + " with " + std::to_string(free_kib) + " KiB free\n" + r.err;
      if (r.exit_code == 0) continue;  // it fit (eval, a small frame)
      ++failed;
      EXPECT_EQ(r.exit_code, 1) << what;
      EXPECT_EQ(lines(r.err), 1) << what;
      const auto now = snapshot(wr.dir);
      if (wr.unit) {
        EXPECT_TRUE(now == previous) << what << "the previous output changed: " << describe(now);
      }
      EXPECT_EQ(names_in(wr.dir).size(), previous.size()) << what << "files were left";
      for (const auto& [name, bytes] : now)
        EXPECT_TRUE(previous.count(name) && (bytes == previous.at(name) || bytes.compare(0, 4, "\x89PNG") == 0))
            << what << name;
    }
    EXPECT_GT(failed, 0) << wr.args << " never ran out of space";
    fs::remove(disk_ / "filler");
    fs::remove_all(wr.dir);
  }
}

TEST_F(Faults, AnOutputThatIsAnInputIsRefusedEvenThroughALink) {
  const fs::path in = out_ / "a.bvh";
  fs::copy_file(clip(), in);
  const std::string before = slurp(in);
  fs::create_hard_link(in, out_ / "hard.bvh");
  fs::create_symlink(in, out_ / "soft.bvh");
  for (const char* out : {"a.bvh", "hard.bvh", "soft.bvh"}) {
    const auto r = run_cli("resample " + in.string() + " -o " + (out_ / out).string() + " --keep-every 8 -q");
    EXPECT_EQ(r.exit_code, 1) << out << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("same file as the input"), std::string::npos) << r.err;
  }
  EXPECT_EQ(slurp(in), before);
  // eval: an output file linked to an input; --merge into one of the merged directories.
  const fs::path e = out_ / "e";
  ASSERT_EQ(run_cli("eval " + in.string() + " --methods slerp --keep-every 4 -q --no-plots -o " + e.string()).exit_code, 0);
  const std::string csv = slurp(e / "errors.csv");
  const auto merge = run_cli("eval --merge " + e.string() + " -o " + e.string() + " -q --no-plots");
  EXPECT_EQ(merge.exit_code, 1) << merge.err;
  EXPECT_NE(merge.err.find("same file as the input"), std::string::npos) << merge.err;
  EXPECT_EQ(slurp(e / "errors.csv"), csv);
  fs::remove(e / "summary.json");
  fs::create_hard_link(in, e / "summary.json");
  const auto over = run_cli("eval " + in.string() + " --methods slerp --keep-every 4 -q --no-plots -o " + e.string());
  EXPECT_EQ(over.exit_code, 1) << over.err;
  EXPECT_EQ(slurp(in), before);
  if (render_built()) {
    const fs::path p = out_ / "p";
    fs::create_directories(p);
    fs::create_hard_link(in, p / "frame_000000.png");
    const auto r = run_cli("render " + in.string() + " -o " + p.string() + " --methods slerp --frames 0 --size 160x120 -q");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("same file as the input"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(in), before);
  }
}

TEST_F(Faults, AReplacedFileKeepsItsModeAndOwnerAndANewFileFollowsTheUmask) {
  const fs::path priv = out_ / "private.bvh", ro = out_ / "readonly.fbx", spec = out_ / "s.bvh";
  write_text(priv, "old\n");
  write_text(ro, "old\n");
  ::chmod(priv.c_str(), 0600);
  ::chmod(ro.c_str(), 0444);
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::chown(priv.c_str(), 65534, 65534), 0);  // nobody
  }
  for (const fs::path& p : {priv, ro})
    ASSERT_EQ(run_cli("resample " + clip().string() + " -o " + p.string() + " -q").exit_code, 0);
  struct stat st {};
  ASSERT_EQ(::stat(priv.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  if (root) {
    EXPECT_EQ(st.st_uid, 65534u);
  }
  ASSERT_EQ(::stat(ro.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0444u);
  // New files: 0666 & ~umask, for our writers and assimp's alike.
  const std::string cmd = "umask 027; " + std::string(ROTINTERP_CLI) + " resample " + clip().string() + " -o " +
                          (out_ / "new.dae").string() + " -q && umask 027 && " + ROTINTERP_CLI + " synth " +
                          spec.string() + " -q";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  for (const fs::path& p : {out_ / "new.dae", spec, fs::path(spec.string() + ".synth")}) {
    ASSERT_EQ(::stat(p.c_str(), &st), 0) << p;
    EXPECT_EQ(st.st_mode & 07777, 0640u) << p;
  }
}

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
