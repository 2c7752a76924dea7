// Placing panels on an image: a grid of equal panels (so panels showing the same
// thing are pixel-identical), leftover pixels as a margin on the right and bottom.
#pragma once

#include <vector>

namespace rotinterp::render {

struct Rect {
  int x = 0, y = 0;  // top-left corner, pixels, y downwards
  int width = 0, height = 0;
};

// Columns for `count` panels in a width × height image that make each panel's
// largest square as big as possible (ties: fewer columns). count ≥ 1.
int automatic_columns(int count, int width, int height);

// `count` equal rectangles, row-major on a grid of `columns`, each
// floor(width / columns) × floor(height / rows).
std::vector<Rect> grid_layout(int count, int columns, int width, int height);

}  // namespace rotinterp::render
