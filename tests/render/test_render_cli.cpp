// `rotinterp render` on a real clip (CMU 01_01, 31 joints): files, sizes, panels,
// determinism, both backends, and a clear line with the right exit code per error.
#include "png_pixels.h"
#include "support/run_cli.h"

#include "rotinterp/render/layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::run_cli;

const std::string kClip = std::string(ROTINTERP_SHARED_DATA) + "/bvh/cmu_01_01.bvh";

// Frames 106 and 118 are halfway between keys 100, 112, 124 (every 12th frame).
struct Args {
  std::string methods = "slerp,slerp,squad";
  std::string frames = "106:118:12";
  std::string size = "420x180";
  std::string extra;
};
Args extra(std::string e) { Args a; a.extra = std::move(e); return a; }
Args frames(std::string f) { Args a; a.frames = std::move(f); return a; }
Args size(std::string z) { Args a; a.size = std::move(z); return a; }
Args methods(std::string m) { Args a; a.methods = std::move(m); return a; }

std::string render_args(const fs::path& dir, const Args& a = {}) {
  return "render " + kClip + " -o " + dir.string() + " --methods " + a.methods + " --keep-every 12 --frames " +
         a.frames + " --size " + a.size + " --view side -q " + a.extra;
}

TEST(RenderCli, ASkeletonWhoseJointsAllLieAtOnePointIsWarnedAbout) {
  // Offsets lost (a reader that dropped the nodes holding them) look like this.
  const fs::path dir = fresh_dir("cli_degenerate");
  fs::create_directories(dir);
  const fs::path clip = dir / "point.bvh";
  std::ofstream(clip) << "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "  JOINT B\n  {\n    OFFSET 0 0 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "    End Site\n    {\n      OFFSET 0 0 0\n    }\n  }\n}\nMOTION\nFrames: 3\n"
                         "Frame Time: 0.1\n0 0 0 0 0 0\n10 0 0 5 0 0\n20 0 0 10 0 0\n";
  const auto r = run_cli("render " + clip.string() + " -o " + (dir / "out").string() +
                         " --methods slerp --keep-every 2 --frames 1 --size 128x96 -q");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + clip.string() + ": all 2 joints lie within 1e-6 units of one point"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

TEST(RenderCli, RealClipGivesFramesOfTheRightSizeWithPanelsThatDifferOnlyBetweenMethods) {
  const fs::path dir = fresh_dir("cli_real");
  const auto r = run_cli(render_args(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "--quiet prints nothing on stderr";
  const auto rects = grid_layout(3, automatic_columns(3, 420, 180), 420, 180);
  for (const char* name : {"frame_000106.png", "frame_000118.png"}) {
    const test::Pixels p = test::read_png(dir / name);
    ASSERT_TRUE(p.ok()) << name;
    EXPECT_EQ(p.width, 420);
    EXPECT_EQ(p.height, 180);
    const auto a = test::crop(p, rects[0]), b = test::crop(p, rects[1]), c = test::crop(p, rects[2]);
    EXPECT_GT(test::distinct_colours(a), 150u) << name;
    EXPECT_EQ(a, b) << name;
    EXPECT_GT(test::differing_pixels(a, c), 20u) << name;
  }
  fs::remove_all(dir);
}

TEST(RenderCli, SameCommandTwiceGivesByteIdenticalPngsOnEachBackend) {
  for (const char* backend : {"osmesa", "egl"}) {
    const fs::path one = fresh_dir(std::string("cli_one_") + backend), two = fresh_dir(std::string("cli_two_") + backend);
    const std::string flags = std::string("--trail LeftArm --sheet --backend ") + backend;
    const auto a = run_cli(render_args(one, extra(flags)));
    const auto b = run_cli(render_args(two, extra(flags)));
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    for (const char* name : {"frame_000106.png", "frame_000118.png", "sheet.png"}) {
      const std::string x = test::slurp(one / name), y = test::slurp(two / name);
      EXPECT_FALSE(x.empty()) << backend << " " << name;
      EXPECT_EQ(x, y) << backend << " " << name;
    }
    fs::remove_all(one);
    fs::remove_all(two);
  }
}

TEST(RenderCli, ErrorsGiveOneLineAndExitCode) {
  const fs::path dir = fresh_dir("cli_errors");
  struct Case {
    std::string args;
    int exit_code;
    const char* expected;
  };
  const Case cases[] = {
      {render_args(dir, extra("--trail NoSuchJoint")), 1, "NoSuchJoint"},
      {render_args(dir, frames("2700:2800")), 1, "runs past the clip's end"},
      {render_args(dir, size("100x30")), 2, "too small"},
      {render_args(dir, size("9000x100")), 2, "8192"},
      {render_args(dir, size("big")), 2, "WxH"},
      {render_args(dir, frames("9:3")), 2, "END is before START"},
      {render_args(dir, methods("slerp,wobble")), 2, "wobble"},
      {render_args(dir, extra("--backend vulkan")), 2, "vulkan"},
      {"render /nonexistent/clip.bvh -o " + dir.string() + " -q", 1, "/nonexistent/clip.bvh"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // the line (+ usage hint)
  }
  EXPECT_FALSE(fs::exists(dir / "frame_000106.png"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
