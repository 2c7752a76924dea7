#include "rotinterp/eval/plots.h"

#include "rotinterp/io/atomic_file.h"

#include <fmt/format.h>
#include <plplot/plplot.h>
#include <sys/types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

// Colour map 0: 0 background (white), 1 axes and text (black), 2 grid (light grey),
// 3… one per method (colour-blind safe, Okabe–Ito).
constexpr int kText = 1, kGrid = 2, kFirstSeries = 3;
constexpr int kPalette[][3] = {{0, 114, 178}, {213, 94, 0}, {0, 158, 115}, {204, 121, 167},
                               {230, 159, 0}, {86, 180, 233}, {120, 120, 120}, {0, 0, 0}};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);
// Smallest angle drawn on a log axis (degrees); exact zeros are drawn there.
constexpr double kLogFloorDeg = 1e-6;

int series_colour(std::size_t i) { return kFirstSeries + static_cast<int>(i % kPaletteSize); }

// PLplot writes the PNG through a stdio stream of ours (plsfile) whose writes go
// to an AtomicOutput, so each one is checked (PLplot and cairo ignore failed
// writes) and nothing needs a path.
struct PageSink {
  AtomicOutput* out;
  std::size_t bytes = 0;
  bool closed = false;
};

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

// Opens a pngcairo page of w × h pixels writing to `file`.
void begin_page(FILE* file, int w, int h) {
  plsdev("pngcairo");
  plsfile(file);
  plspage(0.0, 0.0, w, h, 0, 0);
  plscmap0n(kFirstSeries + kPaletteSize);
  plscol0(0, 255, 255, 255);
  plscol0(kText, 0, 0, 0);
  plscol0(kGrid, 215, 215, 215);
  for (int i = 0; i < kPaletteSize; ++i) plscol0(kFirstSeries + i, kPalette[i][0], kPalette[i][1], kPalette[i][2]);
  plinit();
  pladv(0);
  plschr(0.0, 1.1);
}

// x axis labels 2ᵏ for a log₂ axis; y axis labels 10ᵏ for a log₁₀ axis.
void log_labels(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer) {
  const double v = axis == PL_X_AXIS ? std::pow(2.0, value) : std::pow(10.0, value);
  std::snprintf(label, static_cast<std::size_t>(length), "%g", v);
}

void legend(const std::vector<std::string>& names, const std::vector<int>& styles, bool symbols) {
  const std::size_t n = names.size();
  std::vector<PLINT> opt(n, PL_LEGEND_LINE | (symbols ? PL_LEGEND_SYMBOL : 0)), colours(n), lstyle(n), nsym(n, 1);
  std::vector<PLFLT> widths(n, 2.0), sscale(n, 1.0);
  std::vector<const char*> text(n), sym(n, "#(728)");
  for (std::size_t i = 0; i < n; ++i) {
    colours[i] = series_colour(i);
    lstyle[i] = styles[i];
    text[i] = names[i].c_str();
  }
  std::vector<PLINT> text_colours(n, kText);
  PLFLT w = 0, h = 0;
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE, 0.02, 0.0,
           0.08, 0, kText, 1, static_cast<PLINT>(n), 1, static_cast<PLINT>(n), opt.data(), 1.0, 0.9, 2.0, 0.0,
           text_colours.data(), text.data(), nullptr, nullptr, nullptr, nullptr, colours.data(), lstyle.data(),
           widths.data(), colours.data(), sscale.data(), nsym.data(), sym.data());
}

// Right edge of the plot viewport that leaves room for the legend's longest name.
double viewport_right(const std::vector<std::string>& names) {
  std::size_t longest = 0;
  for (const std::string& n : names) longest = std::max(longest, n.size());
  return std::clamp(0.88 - 0.0115 * static_cast<double>(longest), 0.55, 0.82);
}

// `text` cut to its last `max_chars` characters (UTF-8 safe), with a leading ellipsis.
std::string tail(const std::string& text, std::size_t max_chars) {
  if (text.size() <= max_chars) return text;
  std::size_t start = text.size() - max_chars;
  while (start < text.size() && (static_cast<unsigned char>(text[start]) & 0xC0) == 0x80) ++start;
  return "…" + text.substr(start);
}

// A page drawn into `out` (finished, not committed, by end()).
class Page {
 public:
  Page(AtomicOutput& out, int w, int h) : sink_{&out} {
    file_ = fopencookie(&sink_, "w", cookie_io_functions_t{nullptr, sink_write, nullptr, sink_close});
    if (file_) begin_page(file_, w, h);
  }
  Page(const Page&) = delete;
  Page& operator=(const Page&) = delete;
  ~Page() {
    if (file_ && !ended_) plend();
    if (file_ && !sink_.closed) std::fclose(file_);
  }

  // Ends the page: PLplot encodes the image and closes the stream.
  Status end() {
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

 private:
  PageSink sink_;
  FILE* file_ = nullptr;
  bool ended_ = false;
};

Status spacing_plot(const Summary& s, AtomicOutput& out) {
  std::vector<std::string> methods;
  for (const SummaryEntry& e : s.entries)
    if (std::find(methods.begin(), methods.end(), e.method) == methods.end()) methods.push_back(e.method);
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const SummaryEntry& e : s.entries) {
    const double x = std::log2(std::max(1, e.keep_every));
    xmin = std::min(xmin, x), xmax = std::max(xmax, x);
    for (double v : {e.rms_deg, e.max_deg}) {
      const double y = std::log10(std::max(v, kLogFloorDeg));
      ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
  }
  if (!std::isfinite(xmin)) xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  ymin = std::floor(ymin), ymax = std::ceil(ymax);
  if (ymax <= ymin) ymax = ymin + 1;

  Page page(out, 1200, 800);
  plvpor(0.12, viewport_right(methods), 0.11, 0.90);
  plwind(xmin - 0.25, xmax + 0.25, ymin, ymax);
  plcol0(kGrid);
  plbox("g", 1.0, 0, "g", 1.0, 0);
  plcol0(kText);
  plslabelfunc(log_labels, nullptr);
  plbox("bcnto", 1.0, 0, "bcnstlov", 1.0, 0);
  plslabelfunc(nullptr, nullptr);
  pllab("keys every N frames (N, log scale)", "angle error (degrees, log scale)", "");
  plmtex("t", 2.0, 0.5, 0.5,
         fmt::format("Angular error vs key spacing — {} clip{}; solid RMS, dashed max", s.clips, s.clips == 1 ? "" : "s")
             .c_str());
  for (std::size_t mi = 0; mi < methods.size(); ++mi) {
    for (int which = 0; which < 2; ++which) {
      std::vector<PLFLT> x, y;
      for (const SummaryEntry& e : s.entries) {
        if (e.method != methods[mi]) continue;
        x.push_back(std::log2(std::max(1, e.keep_every)));
        y.push_back(std::log10(std::max(which == 0 ? e.rms_deg : e.max_deg, kLogFloorDeg)));
      }
      plcol0(series_colour(mi));
      plwidth(2.0);
      pllsty(which == 0 ? 1 : 2);
      plline(static_cast<PLINT>(x.size()), x.data(), y.data());
      plstring(static_cast<PLINT>(x.size()), x.data(), y.data(), "#(728)");
    }
  }
  pllsty(1);
  plwidth(1.0);
  legend(methods, std::vector<int>(methods.size(), 1), true);
  return page.end();
}

Status worst_clip_plot(const Summary& s, AtomicOutput& out) {
  std::vector<std::string> methods, joints;
  std::map<std::pair<std::string, std::string>, double> rms;
  double ymax = 0;
  for (const ErrorRow& r : s.worst_clip_rows) {
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
    if (std::find(joints.begin(), joints.end(), r.joint) == joints.end()) joints.push_back(r.joint);
    rms[{r.method, r.joint}] = r.rms_deg;
    ymax = std::max(ymax, r.rms_deg);
  }
  if (!(ymax > 0)) ymax = 1;
  const double xmax = std::max<double>(1, static_cast<double>(joints.size()) - 1);

  Page page(out, 1400, 850);
  plvpor(0.09, viewport_right(methods), 0.26, 0.86);
  plwind(-0.5, xmax + 0.5, 0, ymax * 1.08);
  plcol0(kGrid);
  plbox("", 0, 0, "g", 0, 0);
  plcol0(kText);
  plbox("bct", 1.0, 1, "bcnstv", 0, 0);
  plmtex("l", 3.5, 0.5, 0.5, "RMS angle error (degrees)");
  plmtex("t", 2.6, 0.5, 0.5,
         fmt::format("Per-joint RMS error of the worst clip, keys every {} frames", s.worst_keep_every).c_str());
  plschr(0.0, 0.9);
  plmtex("t", 1.2, 0.5, 0.5, tail(s.worst_clip, 64).c_str());
  plschr(0.0, joints.size() > 40 ? 0.65 : 0.85);
  const double span = xmax + 1.0;
  for (std::size_t i = 0; i < joints.size(); ++i)
    plmtex("bv", 0.7, (static_cast<double>(i) + 0.5) / span, 1.0, joints[i].c_str());
  plschr(0.0, 1.1);
  for (std::size_t mi = 0; mi < methods.size(); ++mi) {
    std::vector<PLFLT> x, y;
    for (std::size_t i = 0; i < joints.size(); ++i) {
      auto it = rms.find({methods[mi], joints[i]});
      if (it == rms.end()) continue;
      x.push_back(static_cast<double>(i));
      y.push_back(it->second);
    }
    plcol0(series_colour(mi));
    plwidth(2.0);
    plline(static_cast<PLINT>(x.size()), x.data(), y.data());
    plstring(static_cast<PLINT>(x.size()), x.data(), y.data(), "#(728)");
  }
  plwidth(1.0);
  legend(methods, std::vector<int>(methods.size(), 1), true);
  return page.end();
}

}  // namespace

Status draw_plots(const Summary& summary, const std::filesystem::path& dir,
                  std::vector<std::unique_ptr<AtomicOutput>>& outputs) {
  outputs.push_back(std::make_unique<AtomicOutput>(dir / kSpacingPlotName, TempKind::unnamed));
  if (Status st = spacing_plot(summary, *outputs.back()); !st) return st;
  outputs.push_back(std::make_unique<AtomicOutput>(dir / kWorstClipPlotName, TempKind::unnamed));
  return worst_clip_plot(summary, *outputs.back());
}

Status write_plots(const Summary& summary, const std::filesystem::path& dir) {
  std::vector<std::unique_ptr<AtomicOutput>> outputs;
  if (Status st = draw_plots(summary, dir, outputs); !st) return st;
  std::vector<AtomicOutput*> all;
  for (auto& o : outputs) all.push_back(o.get());
  return commit_together(all);
}

}  // namespace rotinterp
