// The PLplot page every eval plot is drawn on: the white page and its colour map
// (methods in their palette/method_style.h colours, markers and dashes), log axes,
// series, legends and labels, written through an AtomicOutput.
#pragma once

#include "rotinterp/io/files/atomic_file.h"

#include <plplot/plplot.h>

#include <cstdio>
#include <string>
#include <vector>

namespace rotinterp::plot {

// Colour map 0: 0 background (white), 1 axes and text (black), 2 grid (light grey),
// 3… the method styles (palette/method_style.h), one per slot.
constexpr int kText = 1, kGrid = 2, kFirstSeries = 3;
// Angles below this (degrees) are zero to round-off: drawn as zeros on a log axis
// (a method that reproduces a still clip gives 1e-14°, which would stretch the axis
// over fifteen decades).
constexpr double kZeroDeg = 1e-9;
// Character heights relative to PLplot's default: text, and the markers.
constexpr double kTextScale = 0.8, kMarkerScale = 0.6;

// The y range of an axis: log₁₀ degrees (whole decades, capped at 180°) or, with
// `log` false, degrees; `any` false when no value is positive.
struct LogRange {
  bool log = false;
  bool any = false;
  double lo = 0, hi = 1;
};

// One method's points (and, with `lines`, their line in its dash pattern). On a log
// axis a zero (below kZeroDeg) is an open marker on the bottom edge and breaks the line.
void draw_series(const std::string& method, const std::vector<double>& x, const std::vector<double>& y,
                 const LogRange& yr, bool lines);

// PLplot label function: x axis labels 2ᵏ for a log₂ axis; y axis labels 10ᵏ for a log₁₀ axis.
void log_labels(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer);

// Grid and axes of a plot with log₂ x (or linear x) and log₁₀ y.
void log_axes(bool log_x);

// The methods' legend at `position` (PL_POSITION_*), in `columns` columns, `y_offset`
// (fraction of the viewport's height) from the edge.
void legend(const std::vector<std::string>& names, PLINT position, int columns, double y_offset = 0.01);

// `text` cut to its last `max_chars` characters (UTF-8 safe), with a leading ellipsis.
std::string tail(const std::string& text, std::size_t max_chars);

// Names written vertically under the slots 0 … span − 1 of the x axis.
void joint_labels(const std::vector<std::string>& names, double span, double scale = 0.65);

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
