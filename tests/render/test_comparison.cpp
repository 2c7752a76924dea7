// render_comparison end to end on the synthetic clip: files, sizes, panels that
// differ exactly where the methods differ, determinism, the sheet, errors.
#include "png_pixels.h"
#include "support/run_cli.h"
#include "synthetic_clip.h"

#include "rotinterp/render/comparison.h"
#include "rotinterp/render/layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <unistd.h>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;

// slerp twice and squad: frames 15 and 25 lie halfway between keys (every 10).
ComparisonOptions three_panel_options() {
  ComparisonOptions o;
  o.methods = {"slerp", "slerp", "squad"};
  o.view = View::side;
  o.keep_every = 10;
  o.frames = FrameRange{15, 25, 10};
  o.width = 480;
  o.height = 200;
  return o;
}

TEST(Comparison, WritesOneImagePerFrameWhosePanelsDifferExactlyWhereTheMethodsDiffer) {
  const Clip clip = test::synthetic_clip();
  const fs::path dir = fresh_dir("panels");
  auto result = render_comparison(clip, dir, three_panel_options());
  ASSERT_TRUE(result.ok()) << result.error();
  ASSERT_EQ(result->files.size(), 2u);
  EXPECT_EQ(result->files[0], dir / "frame_000015.png");
  EXPECT_EQ(result->files[1], dir / "frame_000025.png");
  const auto rects = grid_layout(3, automatic_columns(3, 480, 200), 480, 200);
  for (const fs::path& f : result->files) {
    const test::Pixels p = test::read_png(f);
    ASSERT_TRUE(p.ok()) << f;
    EXPECT_EQ(p.width, 480);
    EXPECT_EQ(p.height, 200);
    const auto a = test::crop(p, rects[0]), b = test::crop(p, rects[1]), c = test::crop(p, rects[2]);
    EXPECT_GT(test::distinct_colours(a), 200u) << f << ": blank panel";
    EXPECT_EQ(a, b) << f << ": the same method must give the same pixels";
    EXPECT_GT(test::differing_pixels(a, c), 200u) << f << ": slerp and squad differ between keys";
  }
  fs::remove_all(dir);
}

TEST(Comparison, SameOptionsTwiceGiveByteIdenticalFilesOnBothBackends) {
  const Clip clip = test::synthetic_clip();
  for (Backend backend : {Backend::osmesa, Backend::egl}) {
    ComparisonOptions o = three_panel_options();
    o.backend = backend;
    o.trail_joint = "LeftElbow";
    o.sheet = true;
    const fs::path one = fresh_dir("det1"), two = fresh_dir("det2");
    auto first = render_comparison(clip, one, o);
    auto second = render_comparison(clip, two, o);
    ASSERT_TRUE(first.ok()) << backend_name(backend) << ": " << first.error();
    ASSERT_TRUE(second.ok()) << backend_name(backend) << ": " << second.error();
    ASSERT_EQ(first->files.size(), 3u);
    for (std::size_t i = 0; i < first->files.size(); ++i) {
      EXPECT_EQ(first->files[i].filename(), second->files[i].filename());
      EXPECT_EQ(test::slurp(first->files[i]), test::slurp(second->files[i])) << backend_name(backend) << " " << first->files[i];
    }
    fs::remove_all(one);
    fs::remove_all(two);
  }
}

TEST(Comparison, SheetHasARowPerMethodAndAColumnPerFrame) {
  const Clip clip = test::synthetic_clip();
  ComparisonOptions o = three_panel_options();
  o.frames = FrameRange{5, 35, 10};  // 4 frames
  o.sheet = true;
  const fs::path dir = fresh_dir("sheet");
  auto result = render_comparison(clip, dir, o);
  ASSERT_TRUE(result.ok()) << result.error();
  ASSERT_EQ(result->files.back(), dir / "sheet.png");
  const Rect cell = grid_layout(3, automatic_columns(3, 480, 200), 480, 200).front();
  const test::Pixels sheet = test::read_png(result->files.back());
  ASSERT_TRUE(sheet.ok());
  EXPECT_EQ(sheet.width, 4 * cell.width);
  EXPECT_EQ(sheet.height, 3 * cell.height);
  // Rows 0 and 1 (slerp twice) are identical cell by cell; row 2 (squad) is not.
  const auto cells = grid_layout(12, 4, sheet.width, sheet.height);
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(test::crop(sheet, cells[f]), test::crop(sheet, cells[4 + f])) << "frame column " << f;
    EXPECT_GT(test::differing_pixels(test::crop(sheet, cells[f]), test::crop(sheet, cells[8 + f])), 100u);
  }
  fs::remove_all(dir);
}

// One colour scale for the whole sheet (issue 28: it changed from column to column).
// One colour scale for the run: a frame's panel in its own PNG and its cell in the
// sheet are coloured alike, so by error they differ by the same in both frames, over
// what they differ by method (the control: their titles differ). With a scale per frame (before), the frame with the
// smaller error differed by hundreds of recoloured pixels.
TEST(Comparison, FramesAndSheetCellsShareOneColourScale) {
  const Clip clip = test::synthetic_clip();
  std::size_t control[2] = {0, 0};
  for (Colouring colouring : {Colouring::method, Colouring::error}) {
    ComparisonOptions o = three_panel_options();  // frames 15 and 25
    o.sheet = true;
    o.strip = false;
    o.colouring = colouring;
    const fs::path dir = fresh_dir("one_scale");
    auto result = render_comparison(clip, dir, o);
    ASSERT_TRUE(result.ok()) << result.error();
    const test::Pixels sheet = test::read_png(dir / "sheet.png");
    const Rect panel = grid_layout(3, automatic_columns(3, 480, 200), 480, 200)[2];  // squad
    const auto cells = grid_layout(6, 2, sheet.width, sheet.height);
    std::size_t differing[2];
    for (int f = 0; f < 2; ++f) {
      const test::Pixels frame = test::read_png(dir / (f == 0 ? "frame_000015.png" : "frame_000025.png"));
      differing[f] = test::differing_pixels(test::crop(frame, panel), test::crop(sheet, cells[4 + static_cast<std::size_t>(f)]));
    }
    fs::remove_all(dir);
    if (colouring == Colouring::method) {
      control[0] = differing[0], control[1] = differing[1];
    } else {
      const auto excess = [&](int f) { return static_cast<long>(differing[f]) - static_cast<long>(control[f]); };
      // Alike in both frames (the scale's line sits higher in a cell, which has no corner line).
      EXPECT_LT(std::abs(excess(0) - excess(1)), 40) << "excess over the control: " << excess(0) << ", " << excess(1);
    }
  }
}

TEST(Comparison, ATrailIsDrawnWhenAsked) {
  const Clip clip = test::synthetic_clip();
  ComparisonOptions with = three_panel_options();
  with.frames = FrameRange{15, 15, 1};
  with.trail_joint = "LeftShoulder";
  ComparisonOptions without = with;
  without.trail_joint.clear();
  const fs::path a = fresh_dir("trail_a"), b = fresh_dir("trail_b");
  ASSERT_TRUE(render_comparison(clip, a, with).ok());
  ASSERT_TRUE(render_comparison(clip, b, without).ok());
  const test::Pixels p = test::read_png(a / "frame_000015.png"), q = test::read_png(b / "frame_000015.png");
  EXPECT_GT(test::differing_pixels(p.rgb, q.rgb), 1000u);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(Comparison, BadRequestsFailWithOneLineNamingTheProblem) {
  const Clip clip = test::synthetic_clip();
  const fs::path dir = fresh_dir("errors");
  struct Case {
    void (*change)(ComparisonOptions&);
    const char* expected;
  };
  const Case cases[] = {
      {[](ComparisonOptions& o) { o.trail_joint = "Tail"; }, "no joint 'Tail'"},
      {[](ComparisonOptions& o) { o.frames = FrameRange{10, 61, 1}; }, "runs past the clip's end"},
      {[](ComparisonOptions& o) { o.methods = {"slerp", "nonesuch"}; }, "unknown method 'nonesuch'"},
      {[](ComparisonOptions& o) { o.width = 60; }, "too small"},
      {[](ComparisonOptions& o) { o.height = 9000; }, "8192"},
      {[](ComparisonOptions& o) { o.keep_every = 0; }, "--keep-every"},
  };
  for (const Case& c : cases) {
    ComparisonOptions o = three_panel_options();
    c.change(o);
    auto result = render_comparison(clip, dir, o);
    ASSERT_FALSE(result.ok()) << c.expected;
    EXPECT_NE(result.error().find(c.expected), std::string::npos) << result.error();
    EXPECT_EQ(result.error().find('\n'), std::string::npos) << result.error();
  }
  EXPECT_FALSE(fs::exists(dir / "frame_000015.png")) << "nothing is written on a bad request";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
