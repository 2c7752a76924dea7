// A comparison frame's panels: side by side or overlaid, on the run's one colour scale.
#include "comparison_panels.h"

#include "views.h"

#include "rotinterp/render/colour_map.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace rotinterp::render {

RunScale run_colour_scale(const RebuiltClip& rebuild, std::size_t methods, const std::vector<std::size_t>& frames) {
  std::vector<double> errors, joint_error;
  WorldPose pose;
  double largest = 0.0;
  for (std::size_t f : frames)
    for (std::size_t m = 0; m < methods; ++m) {
      rebuild.method_pose(m, f, pose, &joint_error);
      for (double e : joint_error)
        if (e > 0.0 && std::isfinite(e)) {
          errors.push_back(e);
          largest = std::max(largest, e);
        }
    }
  RunScale s;
  s.deg = error_scale(quantile(std::move(errors), kColourScaleFraction));
  s.saturated = largest > s.deg;
  return s;
}

std::vector<std::shared_ptr<ErrorStrip>> error_strips(const RebuiltClip& rebuild, const PanelPlan& plan,
                                                      std::size_t first, std::size_t last) {
  const std::size_t methods = plan.methods.size();
  ErrorStrip shared;
  for (std::size_t k : rebuild.keys())
    if (k >= first && k <= last) shared.keys.push_back(k - first);
  shared.start_s = rebuild.time(first) - rebuild.time(0);
  shared.end_s = rebuild.time(last) - rebuild.time(0);
  std::vector<StripLine> max_lines(methods), mean_lines(methods);
  std::vector<Quat> local;
  std::vector<double> maxima;
  for (std::size_t m = 0; m < methods; ++m) {
    max_lines[m].colour = mean_lines[m].colour = plan.colours[m];
    mean_lines[m].alpha = 0.5f;
    for (std::size_t f = first; f <= last; ++f) {
      const FrameError e = rebuild.method_rotations(m, f, local);
      max_lines[m].deg.push_back(static_cast<float>(e.max));
      mean_lines[m].deg.push_back(static_cast<float>(e.mean));
      maxima.push_back(e.max);
    }
  }
  shared.scale_deg = error_scale(quantile(maxima, kRobustFraction));
  std::vector<std::shared_ptr<ErrorStrip>> strips;
  if (plan.overlay) {
    auto strip = std::make_shared<ErrorStrip>(shared);
    strip->quantity = "joint error per frame: max over joints, each method";
    strip->lines = std::move(max_lines);
    strips.push_back(std::move(strip));
    return strips;
  }
  for (std::size_t m = 0; m < methods; ++m) {
    auto strip = std::make_shared<ErrorStrip>(shared);
    strip->quantity = "joint error per frame: max over joints (bright), mean (dim)";
    strip->lines = {std::move(mean_lines[m]), std::move(max_lines[m])};
    strips.push_back(std::move(strip));
  }
  return strips;
}

namespace {

std::string error_text(const FrameError& e) { return fmt::format("mean {:.2f}°  max {:.2f}°", e.mean, e.max); }

}  // namespace

FramePanels frame_panels(const RebuiltClip& rebuild, const PanelPlan& plan, std::size_t f, const WorldPose& ghost) {
  const std::size_t methods = plan.methods.size();
  const Skeleton& skeleton = rebuild.skeleton();
  FramePanels out;
  out.errors.resize(methods);
  out.joint_error.resize(methods);
  std::vector<WorldPose> poses(methods);
  std::vector<int> worst(methods, -1);
  for (std::size_t m = 0; m < methods; ++m)
    out.errors[m] = rebuild.method_pose(m, f, poses[m], &out.joint_error[m], &worst[m]);
  const bool is_key = std::binary_search(rebuild.keys().begin(), rebuild.keys().end(), f);
  const std::string key = is_key ? "  (key)" : "";
  Panel base;
  base.ghost = ghost;
  base.corner = fmt::format("frame {}   {:.3f} s", f, rebuild.time(f) - rebuild.time(0));
  if (plan.view) base.view = *plan.view;
  if (!plan.moving.empty()) base.view = plan.moving[f - plan.first];
  auto label_worst = [&](Panel& p, std::size_t m, const std::string& prefix) {
    if (worst[m] < 0 || !(out.errors[m].max > 0.0)) return;
    p.label_joint = worst[m];
    p.joint_label = fmt::format("{}{} {:.1f}°", prefix, skeleton.joints[static_cast<std::size_t>(worst[m])].name,
                                out.errors[m].max);
  };
  if (plan.overlay) {
    Panel p = base;
    p.title = fmt::format("{} over the truth (grey){}", fmt::join(plan.methods, ", "), key);
    p.ghost_legend = "truth (the source's frames)";
    std::size_t worst_method = 0;
    for (std::size_t m = 0; m < methods; ++m) {
      p.figures.push_back(Figure{std::move(poses[m]), plan.colours[m],
                                 fmt::format("{}  joints: {}", plan.methods[m], error_text(out.errors[m]))});
      if (out.errors[m].max > out.errors[worst_method].max) worst_method = m;
    }
    // The worst joint of the worst method, labelled at its pose.
    label_worst(p, worst_method, plan.methods[worst_method] + ": ");
    p.label_figure = static_cast<int>(worst_method);
    if (!plan.strips.empty()) {
      auto strip = std::make_shared<ErrorStrip>(*plan.strips.front());
      strip->cursor = f - plan.first;
      p.strip = std::move(strip);
    }
    out.panels.push_back(std::move(p));
    return out;
  }
  for (std::size_t m = 0; m < methods; ++m) {
    Panel p = base;
    p.title = fmt::format("{}  joints: {}{}", plan.methods[m], error_text(out.errors[m]), key);
    p.colour = plan.colours[m];
    p.pose = std::move(poses[m]);
    if (plan.error_colours) {
      p.colour_scale_deg = plan.scale.deg;
      p.colour_scale_saturated = plan.scale.saturated;
      for (double e : out.joint_error[m]) p.joint_colours.push_back(error_colour(e, plan.scale.deg));
      label_worst(p, m, "");
    }
    if (m < plan.strips.size()) {
      auto strip = std::make_shared<ErrorStrip>(*plan.strips[m]);
      strip->cursor = f - plan.first;
      p.strip = std::move(strip);
    }
    out.panels.push_back(std::move(p));
  }
  return out;
}

Rect sheet_size(const Rect& panel, std::size_t frames, int rows) {
  const int columns = static_cast<int>(frames);
  const double scale = std::min({1.0, static_cast<double>(kMaxImageSide) / (static_cast<double>(panel.width) * columns),
                                 static_cast<double>(kMaxImageSide) / (static_cast<double>(panel.height) * rows)});
  const int cell_w = static_cast<int>(std::floor(panel.width * scale));
  const int cell_h = static_cast<int>(std::floor(panel.height * scale));
  return Rect{0, 0, cell_w * columns, cell_h * rows};
}

std::vector<Panel> sheet_cells(const PanelPlan& plan, const FramePanels& frame, std::size_t f) {
  std::vector<Panel> cells = frame.panels;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Panel& cell = cells[i];
    cell.corner.clear();
    cell.title = plan.overlay ? fmt::format("frame {}", f)
                              : fmt::format("{} #{}  joints {}", plan.methods[i], f, error_text(frame.errors[i]));
  }
  return cells;
}

}  // namespace rotinterp::render
