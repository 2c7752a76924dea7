// The PLplot page of the eval plots: colour map, series, axes, legends, and the
// stream that carries the image into its AtomicOutput.
#include "plot_page.h"

#include "rotinterp/palette/method_style.h"

#include <sys/types.h>

#include <algorithm>
#include <cmath>

namespace rotinterp::plot {

namespace {

// A method's colour map entry, marker and PLplot line style: its registry slot's.
int series_colour(const std::string& method) {
  return kFirstSeries + static_cast<int>(method_slot(method) % kMethodStyles);
}
const char* marker(const std::string& method, bool open = false) {
  const MethodStyle& style = method_style(method_slot(method));
  return open ? style.open_marker : style.marker;
}
int dash(const std::string& method) { return method_style(method_slot(method)).dash; }

ssize_t sink_write(void* cookie, const char* data, size_t size) {
  auto* sink = static_cast<PageSink*>(cookie);
  if (!sink->out->write(data, size)) return -1;
  sink->bytes += size;
  return static_cast<ssize_t>(size);
}
int sink_close(void* cookie) {
  static_cast<PageSink*>(cookie)->closed = true;
  return 0;
}

// Opens a page of w × h pixels on `device` (pngcairo, svgcairo) writing to `file`.
void begin_page(FILE* file, const char* device, int w, int h) {
  plsdev(device);
  plsfile(file);
  plspage(0.0, 0.0, w, h, 0, 0);
  plscmap0n(kFirstSeries + static_cast<int>(kMethodStyles));
  plscol0(0, 255, 255, 255);
  plscol0(kText, 0, 0, 0);
  plscol0(kGrid, 215, 215, 215);
  for (std::size_t i = 0; i < kMethodStyles; ++i) {
    const auto& rgb = method_style(i).rgb;
    plscol0(kFirstSeries + static_cast<int>(i), rgb[0], rgb[1], rgb[2]);
  }
  plinit();
  pladv(0);
}

// Pixels per millimetre of the page (PLplot sizes text in mm).
double px_per_mm() {
  PLFLT xp, yp, x0, x1, y0, y1;
  PLINT xlen, ylen, xoff, yoff;
  plgpage(&xp, &yp, &xlen, &ylen, &xoff, &yoff);
  plgspa(&x0, &x1, &y0, &y1);
  return xlen / (x1 - x0);
}

void marker_size() { plschr(kMarkerPx / px_per_mm(), 1.0); }

}  // namespace

void draw_series(const std::string& method, const std::vector<double>& x, const std::vector<double>& y,
                 const PlotAxis& yr, bool lines) {
  plcol0(series_colour(method));
  plwidth(2.0);
  pllsty(dash(method));
  std::vector<PLFLT> px, py;
  auto flush = [&] {
    if (lines && px.size() > 1) plline(static_cast<PLINT>(px.size()), px.data(), py.data());
    if (!px.empty()) plstring(static_cast<PLINT>(px.size()), px.data(), py.data(), marker(method));
    px.clear(), py.clear();
  };
  marker_size();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!yr.log) {
      px.push_back(x[i]), py.push_back(y[i]);
      continue;
    }
    if (y[i] > kZeroDeg && std::isfinite(y[i])) {
      px.push_back(x[i]), py.push_back(std::log10(y[i]));
      continue;
    }
    flush();
    PLFLT zx = x[i], zy = yr.lo;
    plstring(1, &zx, &zy, marker(method, true));
  }
  flush();
  pllsty(1);
  plwidth(1.0);
}

void draw_frame(const PlotLayout& L, const PlotPanel& p) {
  const double w = L.width, h = L.height;
  plvpor(p.frame.left / w, p.frame.right / w, p.frame.bottom / h, p.frame.top / h);
  plwind(p.x.lo, p.x.hi, p.y.lo, p.y.hi);
  // Ticks 5 px long inside the frame, in axis units.
  const double tx = 5 * (p.x.hi - p.x.lo) / (p.frame.right - p.frame.left);
  const double ty = 5 * (p.y.hi - p.y.lo) / (p.frame.top - p.frame.bottom);
  plcol0(kGrid);
  for (const PlotTick& t : p.y.ticks) pljoin(p.x.lo, t.at, p.x.hi, t.at);
  if (p.slots.empty())
    for (const PlotTick& t : p.x.ticks) pljoin(t.at, p.y.lo, t.at, p.y.hi);
  plcol0(kText);
  plbox("bc", 0, 0, "bc", 0, 0);
  for (const PlotTick& t : p.y.ticks) pljoin(p.x.lo, t.at, p.x.lo + tx, t.at), pljoin(p.x.hi, t.at, p.x.hi - tx, t.at);
  for (const PlotTick& t : p.x.ticks) pljoin(t.at, p.y.lo, t.at, p.y.lo + ty), pljoin(t.at, p.y.hi, t.at, p.y.hi - ty);
}

void draw_texts_and_legend(const PlotLayout& L) {
  const double mm = 1 / px_per_mm();
  plvpor(0, 1, 0, 1);
  plwind(0, L.width, 0, L.height);
  const PlotLegend& g = L.legend;
  if (!g.methods.empty()) {
    plcol0(kText);
    std::vector<PLFLT> bx = {g.box.left, g.box.right, g.box.right, g.box.left, g.box.left},
                       by = {g.box.bottom, g.box.bottom, g.box.top, g.box.top, g.box.bottom};
    plline(5, bx.data(), by.data());
    for (std::size_t i = 0; i < g.methods.size(); ++i) {  // a stretch of the method's line, its marker in the middle
      PLFLT lx[2] = {g.sample_left, g.sample_right}, ly[2] = {g.row_y[i], g.row_y[i]};
      PLFLT mx = 0.5 * (lx[0] + lx[1]), my = g.row_y[i];
      plcol0(series_colour(g.methods[i]));
      plwidth(2.0);
      pllsty(dash(g.methods[i]));
      plline(2, lx, ly);
      pllsty(1);
      plwidth(1.0);
      marker_size();
      plstring(1, &mx, &my, marker(g.methods[i]));
    }
  }
  plcol0(kText);
  for (const PlotText& t : L.texts) {
    plschr(t.height_px * mm, 1.0);
    plptex(t.x, t.y, t.vertical ? 0 : 1, t.vertical ? 1 : 0, t.justify, t.text.c_str());
  }
}

Page::Page(AtomicOutput& out, const char* device, int w, int h) : sink_{&out} {
  file_ = fopencookie(&sink_, "w", cookie_io_functions_t{nullptr, sink_write, nullptr, sink_close});
  if (file_) begin_page(file_, device, w, h);
}

Page::~Page() {
  if (file_ && !ended_) plend();
  if (file_ && !sink_.closed) std::fclose(file_);
}

Status Page::end() {
  const std::string label = sink_.out->target().string();
  if (!file_) return make_error(label + ": cannot write: out of memory");
  plend();
  ended_ = true;
  // PLplot closes the stream it was given; close it here if it did not.
  const bool close_failed = !sink_.closed && std::fclose(file_) != 0;
  sink_.closed = true;
  if (Status s = sink_.out->status(); !s) return s;
  if (close_failed) return make_error(label + ": cannot write the plot");
  if (sink_.bytes == 0) return make_error(label + ": PLplot wrote no image (is plplot-driver-cairo installed?)");
  return sink_.out->finish();
}

}  // namespace rotinterp::plot
