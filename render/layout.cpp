// layout: the panel grid of an image and the parts of one panel.
#include "rotinterp/render/layout.h"

#include <algorithm>
#include <cmath>

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

int corner_text_height(int panel_height) { return std::clamp(static_cast<int>(std::lround(0.045 * panel_height)), 9, 18); }
int corner_text_pad(int panel_height) { return std::max(3, corner_text_height(panel_height) / 3); }

namespace {
// The figure less the band of `lines` corner lines (1.2 line heights each) and
// their padding; at least half the figure stays.
Rect below_text(const Rect& figure, int lines, int panel_height) {
  if (lines <= 0) return figure;
  const int band = 2 * corner_text_pad(panel_height) +
                   static_cast<int>(std::lround(1.2 * lines * corner_text_height(panel_height)));
  const int cut = std::min(band, figure.height / 2);
  return Rect{figure.x, figure.y + cut, figure.width, figure.height - cut};
}
}  // namespace

PanelLayout panel_layout(int width, int height, bool trail, bool strip, bool bar, int corner_lines) {
  const int panel_height = height;
  PanelLayout l;
  l.title_height = std::clamp(static_cast<int>(std::lround(0.075 * height)), 14, 40);
  if (strip) {
    // Room for a label line, a plot and its time labels.
    const int rows = std::clamp(static_cast<int>(std::lround(0.18 * height)), 36, 140);
    if (height - l.title_height - rows >= 32) {
      l.strip = Rect{0, height - rows, width, rows};
      height -= rows;
    }
  }
  const int scene_height = height - l.title_height;
  l.figure = Rect{0, l.title_height, width, scene_height};
  if (bar) {
    const int w = std::clamp(static_cast<int>(std::lround(0.016 * width)), 5, 14);
    const int margin = std::max(4, std::min(width, scene_height) / 40);
    // Below the two lines of text at the figure's top left (frame and time, the scale).
    const int h = static_cast<int>(std::lround(0.5 * scene_height));
    if (h >= 16) l.bar = Rect{margin, l.title_height + static_cast<int>(std::lround(0.32 * scene_height)), w, h};
  }
  if (!trail) {
    l.view = below_text(l.figure, corner_lines, panel_height);
    return l;
  }
  const int margin = std::max(4, std::min(width, scene_height) / 60);
  if (width * 5 <= scene_height * 6) {
    const int side = std::min(width - 2 * margin, static_cast<int>(std::lround(0.34 * scene_height)));
    l.inset = Rect{width - side - margin, height - margin - side, side, side};
    l.figure.height = scene_height - side - margin;
  } else {
    const int side = std::min(scene_height - 2 * margin, static_cast<int>(std::lround(0.34 * width)));
    l.inset = Rect{width - side - margin, l.title_height + margin, side, side};
    l.figure.width = width - side - margin;
  }
  l.view = below_text(l.figure, corner_lines, panel_height);
  return l;
}

std::vector<double> axis_ticks(double lo, double hi, int at_least) {
  if (!(hi > lo) || !std::isfinite(hi - lo)) return {lo};
  const double span = hi - lo;
  double step = std::pow(10.0, std::ceil(std::log10(span)));
  // Smaller 1-2-5 steps until enough multiples fall in [lo, hi].
  auto count = [&](double s) { return std::floor(hi / s + 1e-9) - std::ceil(lo / s - 1e-9) + 1.0; };
  for (int i = 0; count(step) < at_least && i < 60; ++i) {
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    step *= mantissa > 4.0 ? 0.4 : 0.5;  // 5 → 2; 2 → 1 and 1 → 0.5
  }
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) ticks.push_back(k * step + 0.0);  // + 0: no −0
  return ticks;
}

int fitting_height(const TextWidth& width, int pixel_height, float max_width) {
  while (pixel_height > 8 && width(pixel_height) > max_width) --pixel_height;
  return pixel_height;
}

TextItem title_text(const std::string& title, const PanelLayout& layout, int panel_width, const TextWidth& width) {
  const int strip = layout.title_height;
  const float pad = static_cast<float>(std::max(4, strip / 3));
  const int px = fitting_height(width, static_cast<int>(std::lround(0.62 * strip)), static_cast<float>(panel_width) - 2 * pad);
  const float line = static_cast<float>(px) * 1.15f;
  return TextItem{title, pad, std::round((static_cast<float>(strip) - line) * 0.5f), px};
}

TextItem inset_label(const std::string& label, const Rect& inset, const TextWidth& width) {
  const int side = inset.width;
  const float pad = static_cast<float>(std::max(3, side / 40));
  const int px = fitting_height(width, std::clamp(side / 11, 9, 22), static_cast<float>(side) - 2 * pad);
  return TextItem{label, static_cast<float>(inset.x) + pad, static_cast<float>(inset.y) + pad, px};
}

}  // namespace rotinterp::render
