// Nothing lost under faults (README "Robustness"): a write that fails anywhere in
// any writer (a full disk) exits 1 and keeps the previous file; an output that is
// an input is refused; replaced files keep their mode and owner; an eval output
// directory is written as a unit, by one run at a time; a killed run leaves
// nothing; long names work; out of memory is one line.
#include "faults.h"

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using namespace test;

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

}  // namespace
}  // namespace rotinterp
