// Placing panels on an image: a grid of equal panels (so panels showing the same
// thing are pixel-identical), leftover pixels as a margin on the right and bottom;
// and within a panel, its title strip, the figure's viewport, the trail inset and
// the lines of text.
#pragma once

#include <array>
#include <functional>
#include <string>
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

// A width × height panel: a title strip across the top, and under it the scene
// area. With a trail the figure and a square inset share the scene area without
// overlapping: the inset at the bottom right below the figure in tall panels,
// at the top right beside it in wide ones. Rects are in the panel's pixels, y
// downwards.
// With a strip, an error-over-time strip across the bottom (about 0.18 of the
// height, 36…140 rows: a label line, the plot, its time labels) below the scene area; with a colour bar, a narrow vertical
// bar at the figure's left (its labels right of it), over the figure, from 0.32 to
// 0.82 of the scene's height (two lines of text fit above it).
// With `corner_lines` lines of text at the figure's top left (frame and time, the
// colour scale), the camera's viewport is the figure less the band they take, so a
// figure framed to its top (a fixed camera) never reaches under them.
struct PanelLayout {
  int title_height = 0;  // rows at the top
  Rect figure;           // the figure's area, its text at the top left
  Rect view;             // the camera's viewport: the figure less the text band
  Rect inset;            // the trail's square; 0 × 0 without a trail
  Rect strip;            // 0 × 0 without a strip
  Rect bar;              // 0 × 0 without a colour bar
};
PanelLayout panel_layout(int width, int height, bool trail, bool strip = false, bool bar = false, int corner_lines = 0);

// The pixel height of the figure's corner text (frame and time) in a panel
// `panel_height` high, and the padding around its lines.
int corner_text_height(int panel_height);
int corner_text_pad(int panel_height);

// A line of text in a panel.
struct TextItem {
  std::string text;
  float x = 0;           // left, pixels
  float top = 0;         // top of the line box, pixels from the panel's top
  int pixel_height = 0;  // the font's ascent − descent, pixels
  std::array<float, 4> rgba = {0.93f, 0.93f, 0.93f, 1.0f};  // linear RGB, alpha
};

// Tick values of an axis from lo to hi: the multiples of the largest 1-2-5 step
// (…, 0.1, 0.2, 0.5, 1, 2, …) that puts at least `at_least` of them in [lo, hi];
// {lo} when the range is empty.
std::vector<double> axis_ticks(double lo, double hi, int at_least = 3);

// The width in pixels of a text at a pixel height.
using TextWidth = std::function<float(int pixel_height)>;

// The pixel height from `pixel_height` down at which `width` fits `max_width`,
// at least 8 (past that the text is clipped by the panel).
int fitting_height(const TextWidth& width, int pixel_height, float max_width);

// The title, left in the title strip and centred on it vertically, about 0.62 of
// its height and smaller where it is too wide for the panel.
TextItem title_text(const std::string& title, const PanelLayout& layout, int panel_width, const TextWidth& width);

// The trail's label inside the top left of the inset, smaller where too wide for it.
TextItem inset_label(const std::string& label, const Rect& inset, const TextWidth& width);

}  // namespace rotinterp::render
