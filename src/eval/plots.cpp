#include "rotinterp/eval/plots.h"

#include "rotinterp/interp/method_style.h"
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
// 3… the method styles (interp/method_style.h), one per slot.
constexpr int kText = 1, kGrid = 2, kFirstSeries = 3;
// Angles below this (degrees) are zero to round-off: drawn as zeros on a log axis
// (a method that reproduces a still clip gives 1e-14°, which would stretch the axis
// over fifteen decades).
constexpr double kZeroDeg = 1e-9;

// A method's colour map entry, marker and PLplot line style: its registry slot's.
int series_colour(const std::string& method) {
  return kFirstSeries + static_cast<int>(method_slot(method) % kMethodStyles);
}
const char* marker(const std::string& method, bool open = false) {
  const MethodStyle& style = method_style(method_slot(method));
  return open ? style.open_marker : style.marker;
}
int dash(const std::string& method) { return method_style(method_slot(method)).dash; }
// Character heights relative to PLplot's default: text, and the markers.
constexpr double kTextScale = 0.8, kMarkerScale = 0.6;

// Angles stop at 180°: no angle axis runs past it, and legends sit outside the frames
// (room made for one inside stretched an axis to ~30 000°, issue 28).
constexpr double kMaxDeg = 180.0;
const double kMaxLogDeg = std::log10(kMaxDeg);

// The y range of an axis: log₁₀ degrees (whole decades, capped at 180°) or, with
// `log` false, degrees; `any` false when no value is positive.
struct LogRange {
  bool log = false;
  bool any = false;
  double lo = 0, hi = 1;
};
LogRange log_range(const std::vector<double>& values) {
  LogRange r;
  r.log = true;
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (v > kZeroDeg && std::isfinite(v)) lo = std::min(lo, std::log10(v)), hi = std::max(hi, std::log10(v));
  r.any = std::isfinite(lo);
  if (!r.any) lo = 0, hi = 1;
  r.lo = std::floor(lo);
  r.hi = std::min(std::max(std::ceil(hi), r.lo + 1), std::max(kMaxLogDeg, hi));
  return r;
}

struct SpacingPanel {
  const char* title;
  double SummaryEntry::*value;
};
constexpr SpacingPanel kSpacingPanels[] = {{"RMS, all samples", &SummaryEntry::rms_deg},
                                           {"median over clips of the clip RMS", &SummaryEntry::clip_rms_median_deg},
                                           {"max", &SummaryEntry::max_deg}};

LogRange spacing_axis(const Summary& s, const SpacingPanel& panel) {
  std::vector<double> values;
  for (const SummaryEntry& e : s.entries) values.push_back(e.*panel.value);
  return log_range(values);
}

// Each clip at the largest spacing it was evaluated at.
std::map<std::string, int> largest_spacing(const Summary& s) {
  std::map<std::string, int> largest;
  for (const ClipResult& c : s.clip_results) largest[c.clip] = std::max(largest[c.clip], c.keep_every);
  return largest;
}

LogRange clips_axis(const Summary& s) {
  const std::map<std::string, int> largest = largest_spacing(s);
  std::vector<double> values;
  for (const ClipResult& c : s.clip_results)
    if (c.keep_every == largest.at(c.clip)) values.push_back(c.rms_deg);
  return log_range(values);
}

// Linear, from 0 to a quarter above the largest value (capped at 180°).
LogRange worst_clip_axis(const Summary& s) {
  double ymax = 0;
  for (const ErrorRow& r : s.worst_clip_rows) ymax = std::max(ymax, r.rms_deg);
  LogRange r;
  r.any = ymax > 0;
  r.hi = r.any ? std::min(ymax * 1.25, std::max(ymax, kMaxDeg)) : 1.0;
  return r;
}

// Offset of method `i` of `n` around its x value, `dx` apart.
double offset(std::size_t i, std::size_t n, double dx) {
  return (static_cast<double>(i) - 0.5 * static_cast<double>(n - 1)) * dx;
}

// One method's points (and, with `lines`, their line in its dash pattern). On a log
// axis a zero (below kZeroDeg) is an open marker on the bottom edge and breaks the line.
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

void log_labels(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer);

// Grid and axes of a plot with log₂ x and log₁₀ y.
void log_axes(bool log_x) {
  plcol0(kGrid);
  plbox("g", 1.0, 0, "g", 1.0, 0);
  plcol0(kText);
  plslabelfunc(log_labels, nullptr);
  plbox(log_x ? "bcnto" : "bcnt", 1.0, 0, "bcnstlov", 1.0, 0);
  plslabelfunc(nullptr, nullptr);
}

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

// x axis labels 2ᵏ for a log₂ axis; y axis labels 10ᵏ for a log₁₀ axis.
void log_labels(PLINT axis, PLFLT value, char* label, PLINT length, PLPointer) {
  const double v = axis == PL_X_AXIS ? std::pow(2.0, value) : std::pow(10.0, value);
  std::snprintf(label, static_cast<std::size_t>(length), "%g", v);
}

// The methods' legend at `position` (PL_POSITION_*), in `columns` columns, `y_offset`
// (fraction of the viewport's height) from the edge.
void legend(const std::vector<std::string>& names, PLINT position, int columns, double y_offset = 0.01) {
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

// The methods in order of first appearance.
std::vector<std::string> method_names(const Summary& s) {
  std::vector<std::string> methods;
  for (const SummaryEntry& e : s.entries)
    if (std::find(methods.begin(), methods.end(), e.method) == methods.end()) methods.push_back(e.method);
  return methods;
}

// `text` cut to its last `max_chars` characters (UTF-8 safe), with a leading ellipsis.
std::string tail(const std::string& text, std::size_t max_chars) {
  if (text.size() <= max_chars) return text;
  std::size_t start = text.size() - max_chars;
  while (start < text.size() && (static_cast<unsigned char>(text[start]) & 0xC0) == 0x80) ++start;
  return "…" + text.substr(start);
}

// Names written vertically under the slots 0 … span − 1 of the x axis.
void joint_labels(const std::vector<std::string>& names, double span, double scale = 0.65) {
  plschr(0.0, names.size() > 40 ? std::min(scale, 0.5) : scale);
  for (std::size_t i = 0; i < names.size(); ++i)
    plmtex("bv", 0.7, (static_cast<double>(i) + 0.5) / span, 1.0, names[i].c_str());
  plschr(0.0, kTextScale);
}

// A page drawn into `out` (finished, not committed, by end()).
class Page {
 public:
  Page(AtomicOutput& out, const char* device, int w, int h) : sink_{&out} {
    file_ = fopencookie(&sink_, "w", cookie_io_functions_t{nullptr, sink_write, nullptr, sink_close});
    if (file_) begin_page(file_, device, w, h);
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

Status spacing_plot(const Summary& s) {
  const std::vector<std::string> methods = method_names(s);
  double xmin = INFINITY, xmax = -INFINITY;
  for (const SummaryEntry& e : s.entries) {
    const double x = std::log2(std::max(1, e.keep_every));
    xmin = std::min(xmin, x), xmax = std::max(xmax, x);
  }
  if (!std::isfinite(xmin)) xmin = 0, xmax = 1;
  const double dx = 0.05;  // sideways offset between methods, log₂ units
  const double half = dx * 0.5 * static_cast<double>(methods.size());
  constexpr double kBottom = 0.24, kTop = 0.86;
  plvpor(0.07, 0.955, kBottom, kTop);
  plmtex("t", 3.2, 0.5, 0.5,
         fmt::format("Angular error vs key spacing — {} clip{}", s.clips, s.clips == 1 ? "" : "s").c_str());
  plmtex("b", 3.2, 0.5, 0.5, "keys every N frames (log scale)");
  for (int p = 0; p < 3; ++p) {
    const LogRange yr = spacing_axis(s, kSpacingPanels[p]);
    const double left = 0.08 + 0.31 * p;
    plvpor(left, left + 0.255, kBottom, kTop);
    plwind(xmin - 0.3 - half, xmax + 0.3 + half, yr.lo, yr.hi);
    log_axes(true);
    plmtex("t", 1.0, 0.5, 0.5, kSpacingPanels[p].title);
    if (p == 0) plmtex("l", 5.0, 0.5, 0.5, "angle error (degrees, log scale)");
    for (std::size_t mi = 0; mi < methods.size(); ++mi) {
      std::vector<double> x, y;
      for (const SummaryEntry& e : s.entries)
        if (e.method == methods[mi]) {
          x.push_back(std::log2(std::max(1, e.keep_every)) + offset(mi, methods.size(), dx));
          y.push_back(e.*kSpacingPanels[p].value);
        }
      draw_series(methods[mi], x, y, yr, true);
    }
    if (!yr.any) plmtex("t", -4.0, 0.5, 0.5, "all zero");
  }
  plvpor(0.07, 0.955, kBottom, kTop);
  // Below the tick labels and the x axis title (about 4.5 lines of text).
  legend(methods, PL_POSITION_OUTSIDE | PL_POSITION_BOTTOM, std::min<int>(5, static_cast<int>(methods.size())), 0.17);
  return Ok{};
}

Status worst_clip_plot(const Summary& s) {
  std::vector<std::string> methods, joints;
  std::map<std::pair<std::string, std::string>, double> rms;
  for (const ErrorRow& r : s.worst_clip_rows) {
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
    if (std::find(joints.begin(), joints.end(), r.joint) == joints.end()) joints.push_back(r.joint);
    rms[{r.method, r.joint}] = r.rms_deg;
  }
  // Joints with an error in some method, at most kMaxJoints of them (the largest), in skeleton order.
  std::vector<std::pair<double, std::size_t>> largest;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    double most = 0;
    for (const std::string& m : methods)
      if (auto it = rms.find({m, joints[i]}); it != rms.end()) most = std::max(most, it->second);
    if (most > kZeroDeg) largest.push_back({most, i});
  }
  constexpr std::size_t kMaxJoints = 60;
  const std::size_t all_joints = joints.size();
  std::stable_sort(largest.begin(), largest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  if (largest.size() > kMaxJoints) largest.resize(kMaxJoints);
  std::sort(largest.begin(), largest.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  std::vector<std::string> shown;
  for (const auto& l : largest) shown.push_back(joints[l.second]);
  joints = std::move(shown);
  const double xmax = std::max<double>(1, static_cast<double>(joints.size()) - 1);
  plvpor(0.08, 0.97, 0.32, 0.86);
  plwind(-0.5, xmax + 0.5, 0, worst_clip_axis(s).hi);  // a quarter above the largest for the legend
  plcol0(kGrid);
  plbox("", 0, 0, "g", 0, 0);
  plcol0(kText);
  plbox("bct", 1.0, 1, "bcnstv", 0, 0);
  plmtex("l", 3.5, 0.5, 0.5, "RMS angle error (degrees)");
  plmtex("t", 2.6, 0.5, 0.5,
         fmt::format("Per-joint RMS error of the worst clip, keys every {} frames", s.worst_keep_every).c_str());
  plschr(0.0, 0.7);
  const std::string shown_note =
      joints.size() == all_joints
          ? std::string()
          : fmt::format(" — {} of its {} joints: {}", joints.size(), all_joints,
                        all_joints - joints.size() > 0 && joints.size() < kMaxJoints ? "the others have no error"
                                                                                     : "those with the largest error");
  plmtex("t", 1.2, 0.5, 0.5, (tail(s.worst_clip, 80) + shown_note).c_str());
  plschr(0.0, kTextScale);
  std::vector<std::string> labels;
  for (const std::string& j : joints) labels.push_back(tail(j, 24));
  joint_labels(labels, xmax + 1.0);
  const double dx = std::min(0.8 / static_cast<double>(std::max<std::size_t>(methods.size(), 1)), 0.12);
  for (std::size_t mi = 0; mi < methods.size(); ++mi) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < joints.size(); ++i) {
      auto it = rms.find({methods[mi], joints[i]});
      if (it == rms.end()) continue;
      x.push_back(static_cast<double>(i) + offset(mi, methods.size(), dx));
      y.push_back(it->second);
    }
    draw_series(methods[mi], x, y, LogRange{}, joints.size() <= 40);
  }
  legend(methods, PL_POSITION_INSIDE | PL_POSITION_TOP, 4);
  return Ok{};
}

Status clips_plot(const Summary& s) {
  std::vector<std::string> methods = method_names(s), clips;
  std::map<std::string, int> largest = largest_spacing(s);
  for (const ClipResult& c : s.clip_results)
    if (std::find(clips.begin(), clips.end(), c.clip) == clips.end()) clips.push_back(c.clip);
  const LogRange yr = clips_axis(s);
  const double xmax = std::max<double>(1, static_cast<double>(clips.size()) - 1);
  plvpor(0.08, 0.76, 0.40, 0.86);  // the legend on the right
  plwind(-0.5, xmax + 0.5, yr.lo, yr.hi);
  plcol0(kGrid);
  plbox("", 0, 0, "g", 1.0, 0);
  plcol0(kText);
  plslabelfunc(log_labels, nullptr);
  plbox("bct", 1.0, 1, "bcnstlov", 1.0, 0);
  plslabelfunc(nullptr, nullptr);
  plmtex("l", 5.0, 0.5, 0.5, "clip RMS angle error (degrees, log scale)");
  plmtex("t", 2.6, 0.5, 0.5, "RMS error of each clip at the largest spacing it was evaluated at (N in the label)");
  plschr(0.0, 0.7);
  plmtex("t", 1.2, 0.5, 0.5, "open markers on the bottom edge: zero to round-off (below 1e-9°: a still clip, or an exact method)");
  plschr(0.0, kTextScale);
  // Labels without the directory all clips share.
  std::size_t common = clips.empty() ? 0 : clips.front().size();
  for (const std::string& c : clips) {
    std::size_t k = 0;
    while (k < common && k < c.size() && c[k] == clips.front()[k]) ++k;
    common = k;
  }
  if (clips.size() == 1) common = clips.front().size();
  const std::size_t slash = common == 0 ? std::string::npos : clips.front().rfind('/', common - 1);
  common = slash == std::string::npos ? 0 : slash + 1;
  std::vector<std::string> labels;
  for (const std::string& c : clips) labels.push_back(fmt::format("{} (N={})", tail(c.substr(common), 30), largest[c]));
  joint_labels(labels, xmax + 1.0, 0.55);
  const double dx = std::min(0.8 / static_cast<double>(std::max<std::size_t>(methods.size(), 1)), 0.12);
  for (std::size_t mi = 0; mi < methods.size(); ++mi) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < clips.size(); ++i)
      for (const ClipResult& c : s.clip_results)
        if (c.clip == clips[i] && c.method == methods[mi] && c.keep_every == largest[c.clip]) {
          x.push_back(static_cast<double>(i) + offset(mi, methods.size(), dx));
          y.push_back(c.rms_deg);
        }
    draw_series(methods[mi], x, y, yr, false);
  }
  legend(methods, PL_POSITION_OUTSIDE | PL_POSITION_RIGHT, 1, 0.0);
  return Ok{};
}

struct PlotKind {
  const char* png_name;
  int width, height;
  Status (*draw)(const Summary&);
};
constexpr PlotKind kPlots[] = {{kSpacingPlotName, 1500, 700, spacing_plot},
                               {kWorstClipPlotName, 1400, 850, worst_clip_plot},
                               {kClipsPlotName, 1400, 1000, clips_plot}};

std::string svg_name(const char* png_name) {
  const std::string n = png_name;
  return n.substr(0, n.size() - 4) + ".svg";
}

}  // namespace

std::vector<AngleAxis> plot_angle_axes(const Summary& s) {
  auto degrees = [](const char* plot, const LogRange& r) {
    return r.log ? AngleAxis{plot, std::pow(10.0, r.lo), std::pow(10.0, r.hi)} : AngleAxis{plot, r.lo, r.hi};
  };
  std::vector<AngleAxis> axes;
  for (const SpacingPanel& p : kSpacingPanels)
    axes.push_back(degrees(kSpacingPlotName, spacing_axis(s, p)));
  axes.push_back(degrees(kWorstClipPlotName, worst_clip_axis(s)));
  axes.push_back(degrees(kClipsPlotName, clips_axis(s)));
  return axes;
}

std::vector<std::string> plot_file_names() {
  std::vector<std::string> names;
  for (const PlotKind& k : kPlots) names.push_back(k.png_name), names.push_back(svg_name(k.png_name));
  return names;
}

Status draw_plots(const Summary& summary, const std::filesystem::path& dir,
                  std::vector<std::unique_ptr<AtomicOutput>>& outputs) {
  for (const PlotKind& k : kPlots)
    for (const char* device : {"pngcairo", "svgcairo"}) {
      const bool png = device[0] == 'p';
      outputs.push_back(std::make_unique<AtomicOutput>(dir / (png ? std::string(k.png_name) : svg_name(k.png_name)),
                                                       TempKind::unnamed));
      Page page(*outputs.back(), device, k.width, k.height);
      if (Status st = k.draw(summary); !st) return st;
      if (Status st = page.end(); !st) return st;
    }
  return Ok{};
}

Status write_plots(const Summary& summary, const std::filesystem::path& dir) {
  std::vector<std::unique_ptr<AtomicOutput>> outputs;
  if (Status st = draw_plots(summary, dir, outputs); !st) return st;
  std::vector<AtomicOutput*> all;
  for (auto& o : outputs) all.push_back(o.get());
  return commit_together(all);
}

}  // namespace rotinterp
