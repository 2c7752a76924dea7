#include "rotinterp/render/layout.h"

#include <algorithm>

namespace rotinterp::render {

int automatic_columns(int count, int width, int height) {
  if (count <= 1) return 1;
  int best = 1;
  int best_side = -1;
  for (int columns = 1; columns <= count; ++columns) {
    const int rows = (count + columns - 1) / columns;
    const int side = std::min(width / columns, height / rows);
    if (side > best_side) {  // strictly larger: ties keep fewer columns (more rows)
      best_side = side;
      best = columns;
    }
  }
  return best;
}

std::vector<Rect> grid_layout(int count, int columns, int width, int height) {
  std::vector<Rect> rects;
  if (count <= 0 || columns <= 0) return rects;
  columns = std::min(columns, count);
  const int rows = (count + columns - 1) / columns;
  const int w = width / columns, h = height / rows;
  for (int i = 0; i < count; ++i) rects.push_back(Rect{(i % columns) * w, (i / columns) * h, w, h});
  return rects;
}

}  // namespace rotinterp::render
