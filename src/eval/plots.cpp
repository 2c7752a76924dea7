// eval's three plots (error against spacing, the worst clip, every clip), drawn where
// eval/plot_layout.h puts their frames, texts and legends.
#include "rotinterp/eval/plots.h"

#include "plot_page.h"
#include "rotinterp/eval/plot_layout.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

using namespace plot;

// Offset of method `i` of `n` around its x value, `dx` apart.
double offset(std::size_t i, std::size_t n, double dx) {
  return (static_cast<double>(i) - 0.5 * static_cast<double>(n - 1)) * dx;
}

// error_vs_spacing: the three panels' values, as in plot_layout.cpp's panels.
constexpr double SummaryEntry::*kSpacingValues[] = {&SummaryEntry::rms_deg, &SummaryEntry::clip_rms_median_deg,
                                                    &SummaryEntry::max_deg};

void spacing_plot(const Summary& s, const PlotLayout& L) {
  const std::vector<std::string>& methods = L.legend.methods;
  for (std::size_t p = 0; p < L.panels.size(); ++p) {
    const PlotPanel& panel = L.panels[p];
    draw_frame(L, panel);
    for (std::size_t mi = 0; mi < methods.size(); ++mi) {
      std::vector<double> x, y;
      for (const SummaryEntry& e : s.entries)
        if (e.method == methods[mi]) {
          x.push_back(std::log2(std::max(1, e.keep_every)) + offset(mi, methods.size(), panel.method_dx));
          y.push_back(e.*kSpacingValues[p]);
        }
      draw_series(methods[mi], x, y, panel.y, true);
    }
  }
}

// A plot over named slots: `value(method, slot)` gives each point, if any.
template <class Value>
void slot_plot(const PlotLayout& L, bool lines, Value value) {
  const PlotPanel& panel = L.panels.front();
  const std::vector<std::string>& methods = L.legend.methods;
  draw_frame(L, panel);
  for (std::size_t mi = 0; mi < methods.size(); ++mi) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < panel.slots.size(); ++i)
      if (const double* v = value(methods[mi], panel.slots[i])) {
        x.push_back(static_cast<double>(i) + offset(mi, methods.size(), panel.method_dx));
        y.push_back(*v);
      }
    draw_series(methods[mi], x, y, panel.y, lines);
  }
}

void worst_clip_plot(const Summary& s, const PlotLayout& L) {
  std::map<std::pair<std::string, std::string>, double> rms;
  for (const ErrorRow& r : s.worst_clip_rows) rms[{r.method, r.joint}] = r.rms_deg;
  slot_plot(L, L.panels.front().slots.size() <= 40, [&](const std::string& m, const std::string& joint) -> const double* {
    auto it = rms.find({m, joint});
    return it == rms.end() ? nullptr : &it->second;
  });
}

void clips_plot(const Summary& s, const PlotLayout& L) {
  std::map<std::string, int> largest;
  for (const ClipResult& c : s.clip_results) largest[c.clip] = std::max(largest[c.clip], c.keep_every);
  std::map<std::pair<std::string, std::string>, double> rms;
  for (const ClipResult& c : s.clip_results)
    if (c.keep_every == largest[c.clip]) rms[{c.method, c.clip}] = c.rms_deg;
  slot_plot(L, false, [&](const std::string& m, const std::string& clip) -> const double* {
    auto it = rms.find({m, clip});
    return it == rms.end() ? nullptr : &it->second;
  });
}

// In plot_layouts' order.
constexpr void (*kDraw[])(const Summary&, const PlotLayout&) = {spacing_plot, worst_clip_plot, clips_plot};
constexpr const char* kPngNames[] = {kSpacingPlotName, kWorstClipPlotName, kClipsPlotName};

std::string svg_name(const std::string& png_name) { return png_name.substr(0, png_name.size() - 4) + ".svg"; }

}  // namespace

std::vector<std::string> plot_file_names() {
  std::vector<std::string> names;
  for (const char* png : kPngNames) names.push_back(png), names.push_back(svg_name(png));
  return names;
}

Status draw_plots(const Summary& summary, const std::filesystem::path& dir,
                  std::vector<std::unique_ptr<AtomicOutput>>& outputs) {
  const std::vector<PlotLayout> layouts = plot_layouts(summary);
  for (std::size_t k = 0; k < layouts.size(); ++k)
    for (const char* device : {"pngcairo", "svgcairo"}) {
      const PlotLayout& L = layouts[k];
      const bool png = device[0] == 'p';
      outputs.push_back(std::make_unique<AtomicOutput>(dir / (png ? L.png_name : svg_name(L.png_name)), TempKind::unnamed));
      Page page(*outputs.back(), device, L.width, L.height);
      kDraw[k](summary, L);
      draw_texts_and_legend(L);
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
