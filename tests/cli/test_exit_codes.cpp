// Every failure path of every subcommand, as a table: the documented exit code
// (README "Exit codes": 1 bad input or failed run, 2 bad command line, 3 eval with
// some inputs failed), one line on stderr naming the file (or option) and the
// problem, and no output left behind.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

struct Case {
  Case(std::string a, int code, std::vector<std::string> n, std::string out = "", int l = 1)
      : args(std::move(a)), exit_code(code), needles(std::move(n)), output(std::move(out)), lines(l) {}
  std::string args;                  // after the binary; "@" is replaced by the fixture directory
  int exit_code;                     // documented code
  std::vector<std::string> needles;  // each must appear in stderr ("@" replaced too)
  std::string output;                // must not exist afterwards ("@" replaced), empty for none
  int lines;                         // lines on stderr
};

std::string expand(std::string text, const std::string& dir) {
  for (std::size_t p = text.find('@'); p != std::string::npos; p = text.find('@', p + dir.size()))
    text.replace(p, 1, dir);
  return text;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The fixture directory: a small valid clip and every kind of bad input next to it.
class ExitCodes : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rotinterp_exit_codes_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "adir");
    fs::create_directories(dir_ / "emptydir");
    fs::create_directories(dir_ / "taken.bvh");  // a directory where an output file should go
    const std::string good = (dir_ / "good.bvh").string();
    const auto r = run_cli("synth " + good + " --kind smooth --seconds 1 --fps 30 --joints 3 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = test::slurp(good);
    const std::size_t at = text.find("Frames:"), eol = text.find('\n', at);
    ASSERT_NE(at, std::string::npos);
    write_text(dir_ / "beyond.bvh", text.substr(0, at) + "Frames: 100" + text.substr(eol));
    write_text(dir_ / "huge.bvh", text.substr(0, at) + "Frames: 4000000000" + text.substr(eol));
    write_text(dir_ / "nospec.bvh", text);  // a synth clip without its .synth spec
    write_text(dir_ / "empty.bvh", "");
    write_text(dir_ / "notes.xyz", "this is not a motion clip\n");
    write_text(dir_ / "notes.txt", "this is not a motion clip\n");
    write_text(dir_ / "script.py", "import rotinterp\nprint(rotinterp.methods())\n");
    write_text(dir_ / "bad.bvh", "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n");
    write_text(dir_ / "afile", "a plain file where a directory is expected\n");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static void check(const std::vector<Case>& cases) {
    const std::string dir = dir_.string();
    for (const Case& c : cases) {
      const std::string args = expand(c.args, dir);
      const auto start = std::chrono::steady_clock::now();
      const auto r = run_cli(args);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_LT(seconds, 5.0) << args << ": failures are found before any real work (Frames: 4e9 included)";
      EXPECT_EQ(r.exit_code, c.exit_code) << args << "\n" << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), c.lines) << args << "\n" << r.err;
      EXPECT_EQ(r.err.rfind("rotinterp: ", 0), 0u) << args << "\n" << r.err;
      for (const std::string& n : c.needles)
        EXPECT_NE(r.err.find(expand(n, dir)), std::string::npos) << args << "\nmissing '" << expand(n, dir) << "' in\n"
                                                                  << r.err;
      if (!c.output.empty()) {
        EXPECT_FALSE(fs::exists(expand(c.output, dir))) << args;
        fs::remove_all(expand(c.output, dir));
      }
      // Nothing else appears in the fixture directory (temporary files included).
      for (const auto& e : fs::directory_iterator(dir_)) {
        const std::string name = e.path().filename().string();
        EXPECT_TRUE(name == "adir" || name == "emptydir" || name == "good.bvh" || name == "good.bvh.synth" ||
                    name == "beyond.bvh" || name == "huge.bvh" || name == "empty.bvh" || name == "notes.xyz" ||
                    name == "notes.txt" || name == "script.py" || name == "bad.bvh" || name == "afile" || name == "taken.bvh" || name == "nospec.bvh" || name == "ev_partial")
            << args << " left " << name;
      }
    }
  }

  static fs::path dir_;
};

fs::path ExitCodes::dir_;

TEST_F(ExitCodes, ReduceFailuresNameTheFileOrOption) {
  check({
      {"reduce @/missing.bvh -o @/k.json -q", 1, {"@/missing.bvh: no such file"}, "@/k.json"},
      {"reduce @/bad.bvh -o @/k.json -q", 1, {"@/bad.bvh: "}, "@/k.json"},
      {"reduce @/huge.bvh -o @/k.json -q", 1, {"@/huge.bvh: 'Frames: 4000000000'"}, "@/k.json"},
      {"reduce @/good.bvh -o @/afile/k.json -q", 1, {"rotinterp: @/afile: cannot create the output folder"}},
      {"reduce @/good.bvh -o @/k.json --tolerance 0deg -q", 2, {"--tolerance: angle '0deg' must be greater than 0"}, "@/k.json"},
      {"reduce @/good.bvh -o @/k.json --tolerance nanmm -q", 2, {"--tolerance: length 'nanmm' is not a number"}, "@/k.json"},
      {"reduce @/good.bvh -o @/k.json --tolerance 1deg --tolerance-for nosuch=1deg -q", 2,
       {"@/good.bvh has no joint named 'nosuch'"}, "@/k.json"},
      {"reduce @/good.bvh -o @/k.json --tolerance 1deg --tolerance-for x=1 -q", 2, {"--tolerance-for x '1' needs a unit"}, "@/k.json"},
      {"reduce @/good.bvh -o @/k.glb --method squad -q", 2, {"only --method slerp (LINEAR) or gltf-cubic"}, "@/k.glb"},
      {"reduce @/good.bvh -o @/k.txt -q", 2, {"'@/k.txt': unknown format"}, "@/k.txt"},
      {"reduce @/good.bvh -o @/k.json --shell-distance 5 -q", 2, {"--shell-distance needs a length budget"}, "@/k.json"},
      {"reduce @/good.bvh --methods slerp,nope -q", 2, {"unknown method 'nope'"}},
  });
}

TEST_F(ExitCodes, InfoFailuresNameTheFile) {
  check({
      {"info @/missing.bvh", 1, {"@/missing.bvh: no such file"}},
      {"info @/adir", 2, {"for several files or a folder add --summary"}},
      {"info @/empty.bvh", 1, {"@/empty.bvh: the file is empty"}},
      {"info @/notes.xyz", 1, {"@/notes.xyz: not a motion file (formats read: bvh, fbx, glb, gltf, dae"}},
      {"info @/script.py", 1, {"@/script.py: not a motion file (formats read: bvh, fbx, glb, gltf, dae"}},
      {"info @/bad.bvh", 1, {"@/bad.bvh: ", "OFFSET of joint 'Hips'"}},
      {"info @/beyond.bvh", 1, {"@/beyond.bvh: 'Frames: 100' but the file has only 31 data rows"}},
      {"info @/huge.bvh", 1, {"@/huge.bvh: 'Frames: 4000000000'"}},
      {"info --anim 5 @/good.bvh", 1, {"@/good.bvh: ", "there is no animation '5'"}},
      {"info", 2, {"clip is required"}},
      {"info @/good.bvh --frobnicate", 2, {"--frobnicate"}},
  });
}

TEST_F(ExitCodes, ResampleFailuresLeaveNoOutput) {
  const std::string io = "resample @/good.bvh -o @/out.bvh ";
  check({
      {"resample @/missing.bvh -o @/out.bvh --fps 60", 1, {"@/missing.bvh: no such file"}, "@/out.bvh"},
      {"resample @/adir -o @/out.bvh --fps 60", 2, {"'@/out.bvh' is a file name", "need an output directory"}, "@/out.bvh"},
      {"resample @/adir -o @/out --fps 60", 1, {"@/adir: no clip files found"}, "@/out"},
      {"resample @/empty.bvh -o @/out.bvh --fps 60", 1, {"@/empty.bvh: the file is empty"}, "@/out.bvh"},
      {"resample @/notes.xyz -o @/out.bvh --fps 60", 1, {"@/notes.xyz: "}, "@/out.bvh"},
      {"resample @/bad.bvh -o @/out.bvh --fps 60", 1, {"@/bad.bvh: "}, "@/out.bvh"},
      {"resample @/beyond.bvh -o @/out.bvh --fps 60", 1, {"@/beyond.bvh: 'Frames: 100'"}, "@/out.bvh"},
      {"resample @/huge.bvh -o @/out.bvh --fps 60", 1, {"@/huge.bvh: 'Frames: 4000000000'"}, "@/out.bvh"},
      {io + "--fps 0", 2, {"--fps", "greater than 0"}, "@/out.bvh"},
      {io + "--fps abc", 2, {"--fps", "'abc' is not a number"}, "@/out.bvh"},
      {io + "--fps 1000000000", 1, {"@/good.bvh: ", "more than"}, "@/out.bvh"},
      {io + "--keep-every 0", 2, {"--keep-every '0'"}, "@/out.bvh"},
      {io + "--method wobble", 2, {"unknown method 'wobble'", "valid: "}, "@/out.bvh"},
      {io + "--range 1", 2, {"--range '1'", "START:END"}, "@/out.bvh"},
      {io + "--range a:b", 2, {"--range 'a:b'"}, "@/out.bvh"},
      {io + "--range 0:9", 1, {"@/good.bvh: ", "runs past the clip's end (ends at 1 s / frame 30)"}, "@/out.bvh"},
      {io + "--range 0f:31f", 1, {"@/good.bvh: ", "range 0f:31f runs past the clip's end (ends at 1 s / frame 30)"},
       "@/out.bvh"},
      {io + "--range 1.5f:3f", 2, {"--range '1.5f:3f': frames are whole numbers"}, "@/out.bvh"},
      {io + "--method-for Tail=slerp", 1, {"@/good.bvh: ", "'Tail'"}, "@/out.bvh"},
      {"resample @/good.bvh -o @/out.txt --fps 60", 2, {"@/out.txt", "unknown format"}, "@/out.txt"},
      {"resample @/good.bvh -o @/afile/out.bvh --fps 60", 1, {"rotinterp: @/afile: cannot create the output folder"}},
      {"resample @/good.bvh -o @/afile/out.gltf --fps 60", 1, {"rotinterp: @/afile: cannot create the output folder"}},
      {"resample @/good.bvh -o @/taken.bvh --fps 60", 1, {"@/taken.bvh: cannot write"}},
      {"synth @/taken.bvh", 1, {"@/taken.bvh: cannot write"}},
      {"resample @/good.bvh --fps 60", 2, {"--output is required"}},
      {"resample -o @/out.bvh", 2, {"IN is required"}, "@/out.bvh"},
  });
}

TEST_F(ExitCodes, SynthFailuresLeaveNoOutput) {
  check({
      {"synth @/s.bvh --fps 0", 2, {"--fps", "greater than 0"}, "@/s.bvh"},
      {"synth @/s.bvh --fps abc", 2, {"--fps", "'abc'"}, "@/s.bvh"},
      {"synth @/s.bvh --kind dance", 2, {"--kind", "dance"}, "@/s.bvh"},
      {"synth @/s.bvh --seconds 0", 2, {"--seconds '0'"}, "@/s.bvh"},
      {"synth @/s.bvh --seconds x", 2, {"--seconds 'x'"}, "@/s.bvh"},
      {"synth @/s.bvh --seed -1", 2, {"--seed '-1'"}, "@/s.bvh"},
      {"synth @/s.bvh --joints 0", 2, {"--joints '0'"}, "@/s.bvh"},
      {"synth @/s.bvh --seconds 100000 --fps 1000", 2, {"too large"}, "@/s.bvh"},
      {"synth @/s.txt", 2, {"@/s.txt", "unknown format"}, "@/s.txt"},
      // The spec is written first (so that only renames follow the clip's commit).
      {"synth @/afile/s.bvh", 1, {"rotinterp: @/afile: cannot create the output folder"}},
      {"synth", 2, {"--output is required"}},
  });
}

TEST_F(ExitCodes, EvalFailuresNameTheInput) {
  const std::string out = " -o @/ev -q";
  check({
      {"eval @/missing.bvh" + out, 1, {"@/missing.bvh: no such file"}, "@/ev"},
      {"eval @/emptydir" + out, 1, {"@/emptydir: no clip files found"}, "@/ev"},
      {"eval @/good.bvh --keep-every 0" + out, 2, {"--keep-every '0'"}, "@/ev"},
      {"eval @/good.bvh --keep-every x" + out, 2, {"--keep-every 'x'"}, "@/ev"},
      {"eval @/good.bvh --methods wobble" + out, 2, {"unknown method 'wobble'"}, "@/ev"},
      {"eval @/good.bvh --shard 3/2" + out, 2, {"--shard '3/2'"}, "@/ev"},
      {"eval @/good.bvh --jobs abc" + out, 2, {"--jobs"}, "@/ev"},
      {"eval @/good.bvh --subframe -1" + out, 2, {"--subframe"}, "@/ev"},
      {"eval @/good.bvh -o @/afile/ev -q", 1, {"rotinterp: @/afile: cannot create the output folder: a file of that name is in the way"}},
      {"eval --merge @/adir" + out, 1, {"@/adir/summary.json: cannot read"}, "@/ev"},
      {"eval" + out, 2, {"at least one input"}, "@/ev"},
      // A file that fails is reported and the run goes on (nothing else to do here):
      // exit 3, its line, then the count.
      {"eval @/empty.bvh -o @/ev_partial -q", 3, {"@/empty.bvh: the file is empty", "1 of 1 files had failures"}, "", 2},
      {"eval @/huge.bvh -o @/ev_partial -q", 3, {"@/huge.bvh: 'Frames: 4000000000'", "1 of 1 files"}, "", 2},
      {"eval @/bad.bvh -o @/ev_partial -q", 3, {"@/bad.bvh: "}, "", 2},
      {"eval @/notes.txt -o @/ev_partial -q", 3, {"@/notes.txt: not a motion file (formats read: bvh, fbx", "1 of 1"}, "", 2},
      {"eval @/nospec.bvh --truth -o @/ev_partial -q", 3, {"@/nospec.bvh"}, "", 2},
  });
  fs::remove_all(dir_ / "ev_partial");
}

TEST_F(ExitCodes, MethodsRejectsArguments) {
  check({
      {"methods --bogus", 2, {"--bogus"}},
      {"methods extra", 2, {"extra"}},
  });
}

TEST_F(ExitCodes, RenderFailuresLeaveNoOutput) {
  if (run_cli("render --help").exit_code != 0) GTEST_SKIP() << "built without the renderer";
  const std::string io = "render @/good.bvh -o @/r -q --backend osmesa ";
  check({
      {"render @/missing.bvh -o @/r -q", 1, {"@/missing.bvh: no such file"}, "@/r"},
      {"render @/adir -o @/r -q", 1, {"@/adir: is a directory"}, "@/r"},
      {"render @/empty.bvh -o @/r -q", 1, {"@/empty.bvh: the file is empty"}, "@/r"},
      {"render @/bad.bvh -o @/r -q", 1, {"@/bad.bvh: "}, "@/r"},
      {"render @/huge.bvh -o @/r -q", 1, {"@/huge.bvh: 'Frames: 4000000000'"}, "@/r"},
      {io + "--keep-every 0", 2, {"--keep-every"}, "@/r"},
      {io + "--keep-every abc", 2, {"--keep-every"}, "@/r"},
      {io + "--methods slerp,wobble", 2, {"unknown method 'wobble'"}, "@/r"},
      {io + "--frames 9:3", 2, {"END is before START"}, "@/r"},
      {io + "--frames x", 2, {"--frames"}, "@/r"},
      {io + "--frames 0:100", 1, {"@/good.bvh: ", "runs past the clip's end (ends at frame 30, 1 s)"}, "@/r"},
      {io + "--size 0x0", 2, {"--size '0x0'"}, "@/r"},
      {io + "--size big", 2, {"--size", "WxH"}, "@/r"},
      {io + "--size 9000x100", 2, {"8192"}, "@/r"},
      {io + "--view side --trail NoSuchJoint", 1, {"@/good.bvh: ", "NoSuchJoint"}, "@/r"},
      {io + "--backend vulkan", 2, {"vulkan"}, "@/r"},
      {"render @/good.bvh -o @/afile/r -q", 1, {"rotinterp: @/afile: cannot create the output folder"}},
      {"render @/good.bvh -q", 2, {"render: give -o DIR (frame PNGs), --video FILE, or both"}},
  });
}

}  // namespace
}  // namespace rotinterp
