// Where everything on eval's plots goes: the panels' frames and axes, every text with
// the box it takes, and the legend, in pixels. The drawing code (eval/plots.h) draws
// exactly this, so tests check readability on these numbers: ticks, data inside the
// axes, texts that overlap nothing and stay on the page.
#pragma once

#include "rotinterp/eval/plot_axis.h"
#include "rotinterp/eval/summary.h"

#include <string>
#include <vector>

namespace rotinterp {

// A rectangle in pixels, x from the page's left edge, y up from its bottom edge.
struct PlotBox {
  double left = 0, right = 0, bottom = 0, top = 0;
};

// Width of a character as a share of the text height: an upper bound for digits and
// names in PLplot's cairo font (measured: digits 0.88, mixed-case names 0.80,
// lower case 0.72; capital W and M are wider).
constexpr double kCharWidth = 0.9;

// One text: drawn with its reference point at (x, y) — the middle of its capitals'
// height — `justify` along its direction (0 start, 0.5 centre, 1 end); vertical text
// reads bottom to top. `box` is the room it takes, descenders included.
struct PlotText {
  std::string text;
  double x = 0, y = 0, height_px = 0, justify = 0;
  bool vertical = false;
  PlotBox box;
};

struct PlotPanel {
  PlotBox frame;
  PlotAxis x, y;
  // A categorical x axis: slot i at x = i holds slots[i] (a clip id or a joint name);
  // empty for the key-spacing axis.
  std::vector<std::string> slots;
  double method_dx = 0;  // sideways offset between methods, x units
};

struct PlotLegend {
  PlotBox box;
  std::vector<std::string> methods;  // in drawing order, one row each
  std::vector<double> row_y;         // each row's middle
  double row_px = 0, text_px = 0;
  double sample_left = 0, sample_right = 0;  // where each row's line and marker go
};

struct PlotLayout {
  std::string png_name;
  int width = 0, height = 0;  // pixels
  std::vector<PlotPanel> panels;
  std::vector<PlotText> texts;  // titles, tick labels, slot names, legend entries
  PlotLegend legend;
};

// The layouts of the three plots, in the order plot_file_names() lists them.
std::vector<PlotLayout> plot_layouts(const Summary& summary);

// Screen position of an axis value inside a panel frame.
double to_px_x(const PlotPanel& panel, double x);
double to_px_y(const PlotPanel& panel, double y);

}  // namespace rotinterp
