// A figure whose nodes all sit at one point, with a box hanging off each joint's
// pivot, draws as the row of boxes (its mesh End Sites), not as a dot.
#include "png_pixels.h"
#include "support/box_chain_gltf.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

// Columns of the image holding a figure pixel below the text lines: brighter than
// the background and the grid lines.
int figure_columns(const test::Pixels& p) {
  int columns = 0;
  for (int x = 0; x < p.width; ++x)
    for (int y = p.height / 4; y < p.height; ++y) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(p.width) + static_cast<std::size_t>(x));
      if (std::max({p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]}) > 110) {
        ++columns;
        break;
      }
    }
  return columns;
}

TEST(RenderMeshFigure, BoxesHangingOffJointsAtOnePointSpanThePanel) {
  const fs::path dir = test::fresh_dir("mesh_figure");
  fs::create_directories(dir);
  const fs::path clip = dir / "boxes.gltf";
  test::write_box_chain_gltf(clip, 64);
  const auto r = test::run_cli("render " + clip.string() + " -o " + (dir / "out").string() +
                               " --methods slerp --keep-every 1 --frames 0 --size 320x240 --view side --colour method --camera fixed "
                               "--axes off --no-strip -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::Pixels p = test::read_png(dir / "out" / "frame_000000.png");
  ASSERT_TRUE(p.ok());
  // Frame 0 (no turn yet) is the row of boxes; the camera frames the whole clip, where they fan out.
  EXPECT_GT(figure_columns(p), p.width / 4) << "the row of 64 boxes, not a dot";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
