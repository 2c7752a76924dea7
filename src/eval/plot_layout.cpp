// The layouts of eval's three plots: frames, axes, texts and legends in pixels.
#include "rotinterp/eval/plot_layout.h"

#include "rotinterp/eval/plots.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace rotinterp {

namespace {

// Text heights (pixels, capitals): tick labels and panel titles, page titles, and the
// most a slot name may have (less where slots are narrow).
constexpr double kTextPx = 12, kTitlePx = 14, kMaxNamePx = 11, kMinNamePx = 6;
constexpr double kGap = 6;                 // pixels between neighbouring texts and frames
constexpr double kFrameHeightPx = 520;     // frames of the per-clip and per-joint plots
constexpr std::size_t kMaxNameChars = 40;  // clip names, before the ellipsis
constexpr std::size_t kMaxJointChars = 16;
constexpr std::size_t kMaxJoints = 60;

double text_len(const std::string& t, double px) { return static_cast<double>(text_chars(t)) * kCharWidth * px; }

PlotText make_text(std::string t, double x, double y, double px, double justify, bool vertical) {
  PlotText out{std::move(t), x, y, px, justify, vertical, {}};
  const double len = text_len(out.text, px);
  // Capitals span ±0.5 px around the reference, ascenders a little more, descenders to 0.85 px.
  if (vertical) out.box = {x - 0.6 * px, x + 0.85 * px, y - justify * len, y + (1 - justify) * len};
  else out.box = {x - justify * len, x + (1 - justify) * len, y - 0.85 * px, y + 0.6 * px};
  return out;
}

// The methods in order of first appearance.
std::vector<std::string> method_names(const Summary& s) {
  std::vector<std::string> methods;
  for (const SummaryEntry& e : s.entries)
    if (std::find(methods.begin(), methods.end(), e.method) == methods.end()) methods.push_back(e.method);
  return methods;
}

double widest_label(const PlotAxis& a, double px) {
  double w = 0;
  for (const PlotTick& t : a.ticks) w = std::max(w, text_len(t.label, px));
  return w;
}

// Tick labels left of the frame (right-aligned), and below it for a numeric x axis.
void add_tick_labels(PlotLayout& L, const PlotPanel& p) {
  for (const PlotTick& t : p.y.ticks)
    L.texts.push_back(make_text(t.label, p.frame.left - kGap, to_px_y(p, t.at), kTextPx, 1.0, false));
  if (p.slots.empty())
    for (const PlotTick& t : p.x.ticks)
      L.texts.push_back(make_text(t.label, to_px_x(p, t.at), p.frame.bottom - kGap - 0.6 * kTextPx, kTextPx, 0.5, false));
}

// The legend: one row per method, its right edge at `right`, its top at `top`.
PlotLegend make_legend(PlotLayout& L, const std::vector<std::string>& methods, double right, double top) {
  PlotLegend g;
  g.methods = methods;
  g.text_px = kTextPx, g.row_px = 1.8 * kTextPx;
  double w = 0;
  for (const std::string& m : methods) w = std::max(w, text_len(m, kTextPx));
  const double sample = 3.0 * kTextPx;  // the line and marker before each name
  g.box = {right - (kGap + sample + kGap + w + kGap), right, top - (2 * kGap + g.row_px * static_cast<double>(methods.size())), top};
  g.sample_left = g.box.left + kGap, g.sample_right = g.sample_left + sample;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    g.row_y.push_back(g.box.top - kGap - (static_cast<double>(i) + 0.5) * g.row_px);
    L.texts.push_back(make_text(methods[i], g.sample_right + kGap, g.row_y.back(), kTextPx, 0.0, false));
  }
  return g;
}

// A categorical axis over `n` slots.
PlotAxis slot_axis(const std::vector<std::string>& labels) {
  PlotAxis a;
  a.lo = -0.5, a.hi = std::max<double>(1, static_cast<double>(labels.size())) - 0.5;
  a.data_lo = 0, a.data_hi = std::max<double>(0, static_cast<double>(labels.size()) - 1);
  a.any = !labels.empty();
  for (std::size_t i = 0; i < labels.size(); ++i) a.ticks.push_back({static_cast<double>(i), labels[i]});
  return a;
}

// Offset between methods drawn at one slot: all of them within ±0.4 of it.
double slot_dx(std::size_t methods) { return std::min(0.8 / static_cast<double>(std::max<std::size_t>(methods, 1)), 0.12); }

// A page of one frame over named slots (clips, joints): titles above, the y axis left,
// the legend right, the names written vertically below, the page as tall as they need.
PlotLayout slot_page(const char* png, const std::vector<std::string>& titles, const std::string& y_title,
                     const std::vector<std::string>& methods, const std::vector<std::string>& slots,
                     const std::vector<std::string>& labels, PlotAxis y) {
  PlotLayout L;
  L.png_name = png;
  L.width = 1400;
  PlotPanel p;
  p.y = std::move(y);
  p.x = slot_axis(labels);
  p.slots = slots;
  p.method_dx = slot_dx(methods.size());
  p.frame.left = kGap + 1.45 * kTextPx + kGap + widest_label(p.y, kTextPx) + kGap;
  // The legend's width decides the frame's right edge; its height is known from here.
  PlotLayout scratch;
  const PlotLegend probe = make_legend(scratch, methods, L.width - kGap, 0);
  p.frame.right = probe.box.left - 2 * kGap;
  const double slot_px = (p.frame.right - p.frame.left) / (p.x.hi - p.x.lo);
  const double name_px = std::clamp(slot_px / 1.6, kMinNamePx, kMaxNamePx);
  double band = 0;
  for (const std::string& l : labels) band = std::max(band, text_len(l, name_px));
  const double title_band = kGap + 1.6 * kTitlePx + 1.6 * kTextPx * static_cast<double>(titles.size() - 1) + kGap;
  p.frame.bottom = kGap + band + kGap;
  p.frame.top = p.frame.bottom + std::max(kFrameHeightPx, probe.box.top - probe.box.bottom);
  L.height = static_cast<int>(std::ceil(p.frame.top + title_band));
  const double mid = 0.5 * (p.frame.left + p.frame.right);
  for (std::size_t i = 0; i < titles.size(); ++i) {
    const double px = i == 0 ? kTitlePx : kTextPx;
    const double at = L.height - kGap - (i == 0 ? 0.6 * kTitlePx : 1.6 * kTitlePx + (static_cast<double>(i) - 0.4) * 1.6 * kTextPx);
    L.texts.push_back(make_text(titles[i], mid, at, px, 0.5, false));
  }
  L.texts.push_back(make_text(y_title, kGap + 0.6 * kTextPx, 0.5 * (p.frame.bottom + p.frame.top), kTextPx, 0.5, true));
  add_tick_labels(L, p);
  for (std::size_t i = 0; i < labels.size(); ++i)
    L.texts.push_back(make_text(labels[i], to_px_x(p, static_cast<double>(i)),
                                p.frame.bottom - kGap, name_px, 1.0, true));
  L.legend = make_legend(L, methods, L.width - kGap, p.frame.top);
  L.panels.push_back(std::move(p));
  return L;
}

struct SpacingPanel {
  const char* title;
  double SummaryEntry::*value;
};
constexpr SpacingPanel kSpacingPanels[] = {{"RMS, all samples", &SummaryEntry::rms_deg},
                                           {"median over clips of the clip RMS", &SummaryEntry::clip_rms_median_deg},
                                           {"max", &SummaryEntry::max_deg}};

PlotLayout spacing_layout(const Summary& s) {
  PlotLayout L;
  L.png_name = kSpacingPlotName;
  L.width = 1500, L.height = 700;
  const std::vector<std::string> methods = method_names(s);
  std::vector<int> spacings;
  for (const SummaryEntry& e : s.entries) spacings.push_back(e.keep_every);
  const double top = L.height - kGap - 1.6 * kTitlePx - kGap - 1.6 * kTextPx;
  const double bottom = 3 * kGap + 2.9 * kTextPx;  // tick labels and the axis title
  L.legend = make_legend(L, methods, L.width - kGap, top);
  // Across: the y title, then per panel its tick labels and its frame.
  double cursor = kGap + 1.45 * kTextPx + kGap, fixed = cursor;
  std::vector<PlotPanel> panels(3);
  for (std::size_t i = 0; i < 3; ++i) {
    std::vector<double> values;
    for (const SummaryEntry& e : s.entries) values.push_back(e.*kSpacingPanels[i].value);
    panels[i].y = angle_axis(values, AxisScale::log);
    panels[i].x = spacing_axis(spacings);
    panels[i].method_dx = 0.05;
    fixed += widest_label(panels[i].y, kTextPx) + kGap + 3 * kGap;
  }
  const double width = (L.legend.box.left - kGap - fixed) / 3;
  for (std::size_t i = 0; i < 3; ++i) {
    PlotPanel& p = panels[i];
    cursor += widest_label(p.y, kTextPx) + kGap;
    p.frame = {cursor, cursor + width, bottom, top};
    cursor = p.frame.right + 3 * kGap;
    add_tick_labels(L, p);
    const std::string title = std::string(kSpacingPanels[i].title) + (p.y.any ? "" : " (all zero)");
    L.texts.push_back(make_text(title, 0.5 * (p.frame.left + p.frame.right), top + kGap + 0.85 * kTextPx, kTextPx, 0.5, false));
  }
  const double mid = 0.5 * (panels.front().frame.left + panels.back().frame.right);
  L.texts.push_back(make_text(fmt::format("Angular error vs key spacing — {} clip{}", s.clips, s.clips == 1 ? "" : "s"),
                              mid, L.height - kGap - 0.6 * kTitlePx, kTitlePx, 0.5, false));
  L.texts.push_back(make_text("keys every N frames (log scale)", mid, bottom - 2 * kGap - 2.05 * kTextPx, kTextPx, 0.5, false));
  L.texts.push_back(make_text("angle error (degrees, log scale)", kGap + 0.6 * kTextPx, 0.5 * (bottom + top), kTextPx, 0.5, true));
  L.panels = std::move(panels);
  return L;
}

PlotLayout worst_clip_layout(const Summary& s) {
  std::vector<std::string> methods, joints;
  std::map<std::string, double> most;  // a joint's largest RMS over the methods
  for (const ErrorRow& r : s.worst_clip_rows) {
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
    if (std::find(joints.begin(), joints.end(), r.joint) == joints.end()) joints.push_back(r.joint);
    most[r.joint] = std::max(most[r.joint], r.rms_deg);
  }
  // Joints with an error, at most kMaxJoints of them (the largest), in skeleton order.
  std::vector<std::pair<double, std::size_t>> largest;
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (most[joints[i]] > kZeroDeg) largest.push_back({most[joints[i]], i});
  std::stable_sort(largest.begin(), largest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  if (largest.size() > kMaxJoints) largest.resize(kMaxJoints);
  std::sort(largest.begin(), largest.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  std::vector<std::string> shown;
  for (const auto& l : largest) shown.push_back(joints[l.second]);
  std::vector<double> values;
  for (const ErrorRow& r : s.worst_clip_rows)
    if (std::find(shown.begin(), shown.end(), r.joint) != shown.end()) values.push_back(r.rms_deg);
  const std::string note =
      shown.size() == joints.size()
          ? std::string()
          : fmt::format(" — {} of its {} joints: {}", shown.size(), joints.size(),
                        shown.size() < kMaxJoints ? "the others have no error" : "those with the largest error");
  // The clip's file name, shortened in the middle if the line would not fit the page.
  const std::size_t room = static_cast<std::size_t>(1300 / (kCharWidth * kTextPx)) - text_chars(note);
  const std::vector<std::string> titles = {
      fmt::format("Per-joint RMS error of the worst clip, keys every {} frames", s.worst_keep_every),
      middle_ellipsis(clip_file_name(s.worst_clip), std::max<std::size_t>(room, 20)) + note};
  return slot_page(kWorstClipPlotName, titles, "RMS angle error (degrees)", methods, shown,
                   short_labels(shown, kMaxJointChars), angle_axis(values, AxisScale::automatic));
}

PlotLayout clips_layout(const Summary& s) {
  std::vector<std::string> clips;
  std::map<std::string, int> largest;
  for (const ClipResult& c : s.clip_results) {
    if (std::find(clips.begin(), clips.end(), c.clip) == clips.end()) clips.push_back(c.clip);
    largest[c.clip] = std::max(largest[c.clip], c.keep_every);
  }
  std::vector<double> values;
  bool zeros = false;
  for (const ClipResult& c : s.clip_results)
    if (c.keep_every == largest[c.clip]) values.push_back(c.rms_deg), zeros |= !(c.rms_deg > kZeroDeg);
  PlotAxis y = angle_axis(values, AxisScale::automatic);
  std::vector<std::string> labels = short_labels(clip_labels(clips), kMaxNameChars);
  for (std::size_t i = 0; i < clips.size(); ++i) labels[i] += fmt::format(" (N={})", largest[clips[i]]);
  std::vector<std::string> titles = {"RMS error of each clip at the largest spacing it was evaluated at (N in the label)"};
  if (zeros && y.log) titles.push_back("open markers on the bottom edge: zero to round-off (below 1e-9°: a still clip, or an exact method)");
  return slot_page(kClipsPlotName, titles, y.log ? "clip RMS angle error (degrees, log scale)" : "clip RMS angle error (degrees)",
                   method_names(s), clips, labels, std::move(y));
}

}  // namespace

double to_px_x(const PlotPanel& p, double x) {
  return p.frame.left + (x - p.x.lo) / (p.x.hi - p.x.lo) * (p.frame.right - p.frame.left);
}
double to_px_y(const PlotPanel& p, double y) {
  return p.frame.bottom + (y - p.y.lo) / (p.y.hi - p.y.lo) * (p.frame.top - p.frame.bottom);
}

std::vector<PlotLayout> plot_layouts(const Summary& s) {
  return {spacing_layout(s), worst_clip_layout(s), clips_layout(s)};
}

}  // namespace rotinterp
