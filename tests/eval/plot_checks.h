// Readability of a plot, checked on the numbers it is drawn with (eval/plot_layout.h):
// every numeric axis labelled at least three times, its values inside it and filling
// at least half of it, every text on the page and clear of every other text, of the
// frames and of the legend.
#pragma once

#include "rotinterp/eval/plot_layout.h"

#include <cmath>
#include <string>
#include <vector>

namespace rotinterp::test {

inline bool overlap(const PlotBox& a, const PlotBox& b) {
  return a.left < b.right && b.left < a.right && a.bottom < b.top && b.bottom < a.top;
}

inline std::string box_text(const PlotBox& b) {
  return "[" + std::to_string(b.left) + ", " + std::to_string(b.right) + "] × [" + std::to_string(b.bottom) + ", " +
         std::to_string(b.top) + "]";
}

// The problems of one axis: `name` says which. `fill`: whether its values must fill
// half of it (not the key spacings: two spacings on three labelled powers of two).
inline std::vector<std::string> axis_problems(const PlotAxis& a, const std::string& name, bool fill = true) {
  std::vector<std::string> out;
  if (a.ticks.size() < 3) out.push_back(name + ": " + std::to_string(a.ticks.size()) + " labelled ticks");
  for (const PlotTick& t : a.ticks)
    if (t.at < a.lo - 1e-9 || t.at > a.hi + 1e-9) out.push_back(name + ": tick " + t.label + " outside the axis");
  if (a.data_lo < a.lo - 1e-9 || a.data_hi > a.hi + 1e-9)
    out.push_back(name + ": values " + std::to_string(a.data_lo) + "…" + std::to_string(a.data_hi) + " outside " +
                  std::to_string(a.lo) + "…" + std::to_string(a.hi));
  const double span = a.hi - a.lo, filled = a.data_hi - a.data_lo;
  // Values nearer each other than the narrowest axis fill less, in its middle half.
  const double narrowest = a.log ? kMinLogSpan : kMinLinearSpan * (a.log ? 1.0 : std::abs(a.data_hi));
  const bool one_value = filled < narrowest * (1 + 1e-9);
  if (fill && a.any && !one_value && filled < 0.5 * span)
    out.push_back(name + ": values fill " + std::to_string(100 * filled / span) + " % of the axis");
  if (fill && a.any && one_value && std::abs(a.data_lo + a.data_hi - a.lo - a.hi) > 0.5 * span)
    out.push_back(name + ": values all near one, off the middle of the axis");
  return out;
}

inline std::vector<std::string> readability_problems(const PlotLayout& L) {
  std::vector<std::string> out;
  auto add = [&](std::vector<std::string> more) { out.insert(out.end(), more.begin(), more.end()); };
  for (std::size_t i = 0; i < L.panels.size(); ++i) {
    const PlotPanel& p = L.panels[i];
    const std::string name = L.png_name + " panel " + std::to_string(i);
    add(axis_problems(p.y, name + " y"));
    if (p.slots.empty()) add(axis_problems(p.x, name + " x", false));
    if (overlap(L.legend.box, p.frame)) out.push_back(name + ": the legend covers the frame");
  }
  const PlotBox page{0, double(L.width), 0, double(L.height)};
  auto on_page = [&](const PlotBox& b) {
    return b.left >= page.left - 1e-9 && b.right <= page.right + 1e-9 && b.bottom >= -1e-9 && b.top <= page.top + 1e-9;
  };
  if (!L.legend.methods.empty() && !on_page(L.legend.box)) out.push_back(L.png_name + ": the legend leaves the page");
  for (std::size_t i = 0; i < L.texts.size(); ++i) {
    const PlotText& t = L.texts[i];
    const std::string what = L.png_name + ": \"" + t.text + "\" " + box_text(t.box);
    if (!on_page(t.box)) out.push_back(what + " is cut by the page's edge");
    for (const PlotPanel& p : L.panels)
      if (overlap(t.box, p.frame)) out.push_back(what + " lies inside a frame");
    for (std::size_t j = i + 1; j < L.texts.size(); ++j)
      if (overlap(t.box, L.texts[j].box)) out.push_back(what + " overlaps \"" + L.texts[j].text + "\"");
  }
  return out;
}

}  // namespace rotinterp::test
