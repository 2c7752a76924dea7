// The PLplot page every eval plot is drawn on: the white page and its colour map
// (methods in their palette/method_style.h colours, markers and dashes), frames,
// series, texts and legends where eval/plot_layout.h puts them, written through an AtomicOutput.
#pragma once

#include "rotinterp/eval/plot_layout.h"
#include "rotinterp/io/files/atomic_file.h"

#include <plplot/plplot.h>

#include <cstdio>
#include <string>
#include <vector>

namespace rotinterp::plot {

// Colour map 0: 0 background (white), 1 axes and text (black), 2 grid (light grey),
// 3… the method styles (palette/method_style.h), one per slot.
constexpr int kText = 1, kGrid = 2, kFirstSeries = 3;
// Height of a marker glyph, pixels.
constexpr double kMarkerPx = 10;

// One method's points (and, with `lines`, their line in its dash pattern), in the
// current window. On a log axis (log₁₀ units) a zero (below kZeroDeg) is an open
// marker on the bottom edge and breaks the line.
void draw_series(const std::string& method, const std::vector<double>& x, const std::vector<double>& y,
                 const PlotAxis& y_axis, bool lines);

// A panel's frame, grid and tick marks at its labelled ticks; leaves the panel's
// window set for draw_series.
void draw_frame(const PlotLayout& layout, const PlotPanel& panel);

// Every text of the layout and its legend, where the layout puts them.
void draw_texts_and_legend(const PlotLayout& layout);

// PLplot writes the image through a stdio stream of ours (plsfile) whose writes go
// to an AtomicOutput, so each one is checked (PLplot and cairo ignore failed
// writes) and nothing needs a path.
struct PageSink {
  AtomicOutput* out;
  std::size_t bytes = 0;
  bool closed = false;
};

// A page of w × h pixels on `device` (pngcairo, svgcairo), drawn into `out`
// (finished, not committed, by end()).
class Page {
 public:
  Page(AtomicOutput& out, const char* device, int w, int h);
  Page(const Page&) = delete;
  Page& operator=(const Page&) = delete;
  ~Page();

  // Ends the page: PLplot encodes the image and closes the stream.
  Status end();


 private:
  PageSink sink_;
  FILE* file_ = nullptr;
  bool ended_ = false;
};

}  // namespace rotinterp::plot
