// eval's three plots (error against spacing, the worst clip, every clip) and their angle axes.
#include "rotinterp/eval/plots.h"

#include "plot_page.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

using namespace plot;

// Angles stop at 180°: no angle axis runs past it, and legends sit outside the frames
// (room made for one inside stretched an axis to ~30 000°, issue 28).
constexpr double kMaxDeg = 180.0;
const double kMaxLogDeg = std::log10(kMaxDeg);

// The log₁₀ range of `values`: whole decades, capped at 180°; `any` false when no
// value is positive.
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


// The methods in order of first appearance.
std::vector<std::string> method_names(const Summary& s) {
  std::vector<std::string> methods;
  for (const SummaryEntry& e : s.entries)
    if (std::find(methods.begin(), methods.end(), e.method) == methods.end()) methods.push_back(e.method);
  return methods;
}


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
