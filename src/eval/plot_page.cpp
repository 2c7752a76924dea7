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
  plschr(0.0, kTextScale);
}

}  // namespace

void log_labels(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer) {
  const double v = axis == PL_X_AXIS ? std::pow(2.0, value) : std::pow(10.0, value);
  std::snprintf(label, static_cast<std::size_t>(length), "%g", v);
}

void draw_series(const std::string& method, const std::vector<double>& x, const std::vector<double>& y, const LogRange& yr,
                 bool lines) {
  plcol0(series_colour(method));
  plwidth(2.0);
  pllsty(dash(method));
  std::vector<PLFLT> px, py;
  auto flush = [&] {
    if (lines && px.size() > 1) plline(static_cast<PLINT>(px.size()), px.data(), py.data());
    plschr(0.0, kMarkerScale);
    if (!px.empty()) plstring(static_cast<PLINT>(px.size()), px.data(), py.data(), marker(method));
    plschr(0.0, kTextScale);
    px.clear(), py.clear();
  };
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
    plschr(0.0, kMarkerScale);
    plstring(1, &zx, &zy, marker(method, true));
    plschr(0.0, kTextScale);
  }
  flush();
  pllsty(1);
  plwidth(1.0);
}

void log_axes(bool log_x) {
  plcol0(kGrid);
  plbox("g", 1.0, 0, "g", 1.0, 0);
  plcol0(kText);
  plslabelfunc(log_labels, nullptr);
  plbox(log_x ? "bcnto" : "bcnt", 1.0, 0, "bcnstlov", 1.0, 0);
  plslabelfunc(nullptr, nullptr);
}

void legend(const std::vector<std::string>& names, PLINT position, int columns, double y_offset) {
  const std::size_t n = names.size();
  std::vector<PLINT> opt(n, PL_LEGEND_LINE | PL_LEGEND_SYMBOL), colours(n), lstyle(n), nsym(n, 1);
  std::vector<PLFLT> widths(n, 2.0), sscale(n, 0.8);
  std::vector<const char*> text(n), sym(n);
  for (std::size_t i = 0; i < n; ++i) {
    colours[i] = series_colour(names[i]);
    lstyle[i] = dash(names[i]);
    text[i] = names[i].c_str();
    sym[i] = marker(names[i]);
  }
  std::vector<PLINT> text_colours(n, kText);
  const PLINT ncol = std::max(1, columns), nrow = static_cast<PLINT>((static_cast<int>(n) + ncol - 1) / ncol);
  PLFLT w = 0, h = 0;
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX | (ncol > 1 ? PL_LEGEND_ROW_MAJOR : 0), position, 0.01,
           y_offset, ncol > 1 ? 0.04 : 0.1, 0, kText, 1, nrow, ncol, static_cast<PLINT>(n), opt.data(), 0.8, 0.75, 1.8,
           0.0, text_colours.data(), text.data(), nullptr, nullptr,
           nullptr, nullptr, colours.data(), lstyle.data(), widths.data(), colours.data(), sscale.data(), nsym.data(),
           sym.data());
}

// `text` cut to its last `max_chars` characters (UTF-8 safe), with a leading ellipsis.
std::string tail(const std::string& text, std::size_t max_chars) {
  if (text.size() <= max_chars) return text;
  std::size_t start = text.size() - max_chars;
  while (start < text.size() && (static_cast<unsigned char>(text[start]) & 0xC0) == 0x80) ++start;
  return "…" + text.substr(start);
}

// Names written vertically under the slots 0 … span − 1 of the x axis.
void joint_labels(const std::vector<std::string>& names, double span, double scale) {
  plschr(0.0, names.size() > 40 ? std::min(scale, 0.5) : scale);
  for (std::size_t i = 0; i < names.size(); ++i)
    plmtex("bv", 0.7, (static_cast<double>(i) + 0.5) / span, 1.0, names[i].c_str());
  plschr(0.0, kTextScale);
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
