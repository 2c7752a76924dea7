// The figure never reaches under the frame's corner text: a fixed camera frames a
// tall figure to the top of its viewport, which starts below the text band.
#include "png_pixels.h"
#include "support/run_cli.h"

#include "rotinterp/render/layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

TEST(Layout, TheCamerasViewportStartsBelowTheCornerLines) {
  for (bool trail : {false, true})
    for (int lines : {0, 1, 2}) {
      const PanelLayout l = panel_layout(480, 360, trail, true, lines == 2, lines);
      const int band = lines == 0 ? 0 : 2 * corner_text_pad(360) + static_cast<int>(std::lround(1.2 * lines * corner_text_height(360)));
      EXPECT_EQ(l.view.y, l.figure.y + band) << lines;
      EXPECT_EQ(l.view.y + l.view.height, l.figure.y + l.figure.height);
      EXPECT_EQ(l.view.x, l.figure.x);
      EXPECT_EQ(l.view.width, l.figure.width);
    }
}

TEST(RenderFraming, AFixedCameraKeepsATallFigureClearOfTheFrameLabel) {
  const fs::path dir = test::fresh_dir("below_text");
  fs::create_directories(dir);
  const fs::path clip = dir / "pole.bvh";  // a pole 40 units high that sways a little
  std::ofstream(clip) << "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "  JOINT B\n  {\n    OFFSET 0 20 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "    End Site\n    {\n      OFFSET 0 20 0\n    }\n  }\n}\nMOTION\nFrames: 3\n"
                         "Frame Time: 0.1\n0 0 0 0 0 0\n2 0 0 2 0 0\n4 0 0 4 0 0\n";
  const auto r = test::run_cli("render " + clip.string() + " -o " + (dir / "out").string() +
                               " --methods squad --keep-every 2 --frames 1 --size 480x360 --view side --colour method "  // squad: vermillion
                               "--camera fixed --no-strip -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::Pixels p = test::read_png(dir / "out" / "frame_000001.png");
  ASSERT_TRUE(p.ok());
  const PanelLayout l = panel_layout(480, 360, false, false, false, 2);  // as the renderer lays out every panel
  auto orange_rows = [&](int y0, int y1) {
    int rows = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < p.width; ++x) {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) + static_cast<std::size_t>(x));
        if (p.rgb[i] > 120 && p.rgb[i] > p.rgb[i + 2] + 60 && p.rgb[i] > p.rgb[i + 1] + 20) {
          ++rows;
          break;
        }
      }
    return rows;
  };
  EXPECT_GT(orange_rows(l.view.y, p.height), l.view.height / 2) << "the pole fills the viewport's height";
  EXPECT_EQ(orange_rows(l.figure.y, l.view.y), 0) << "nothing of it under the 'frame 1' line";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
