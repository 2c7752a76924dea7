// What the renderer draws over a panel's figure: the trail inset, the colour bar,
// the error strip and the joint label.
#include "renderer_impl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rotinterp::render {

namespace {

// Pixels of a width × height viewport (x right, y down, from its top-left corner)
// to clip space, for overlays drawn as lines.
Eigen::Matrix4f pixel_space(int width, int height) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 2.0f / static_cast<float>(width);
  m(0, 3) = -1.0f;
  m(1, 1) = -2.0f / static_cast<float>(height);
  m(1, 3) = 1.0f;
  m(2, 2) = 0.0f;
  return m;
}

// A line segment between two pixel positions, into a line list.
void pixel_line(LineList& lines, float x0, float y0, float x1, float y1, const float rgba[4]) {
  lines.insert(lines.end(), {x0, y0, 0.0f, rgba[0], rgba[1], rgba[2], rgba[3], x1, y1, 0.0f, rgba[0], rgba[1], rgba[2], rgba[3]});
}

}  // namespace

void Renderer::Impl::draw_trail(const Panel& panel, const Trail& trail, const Rect& inset, int height) {
  gl.Enable(GL_SCISSOR_TEST);
  scissor(inset, height);
  gl.ClearColor(kInsetBackground[0], kInsetBackground[1], kInsetBackground[2], 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  viewport(inset, height);
  const TrailView view = trail_view(trail.reference, trail.method, scene.view);
  draw_lines(sphere_lines, to_float(view.camera.projection() * view.camera.view()));
  use_mesh_program(view.camera, view.zoom * kTrailReferenceRadius, inset.height);
  trail_figure(trail, panel.colour, view.zoom, solid, translucent);
  draw_opaque(solid);
  draw_translucent(translucent);
  gl.Disable(GL_SCISSOR_TEST);
  if (!trail.label.empty()) texts.push_back(inset_label(trail.label, inset, text_width(trail.label)));
}

// A vertical viridis bar from 0 (bottom) to the panel's scale (top), one line
// per row, labelled in degrees at both ends.
void Renderer::Impl::draw_colour_bar(const Panel& panel, const Rect& bar, int width, int height) {
  LineList lines;
  for (int row = 0; row < bar.height; ++row) {
    const Colour c = viridis(static_cast<double>(bar.height - 1 - row) / std::max(1, bar.height - 1));
    const float rgba[4] = {c[0], c[1], c[2], 1.0f};
    const float y = static_cast<float>(bar.y + row) + 0.5f;
    pixel_line(lines, static_cast<float>(bar.x), y, static_cast<float>(bar.x + bar.width), y, rgba);
  }
  gl.Disable(GL_DEPTH_TEST);
  gl.Viewport(0, 0, width, height);
  draw_lines(lines, pixel_space(width, height));
  gl.Enable(GL_DEPTH_TEST);
  const int px = std::clamp(bar.height / 9, 9, 16);
  const float x = static_cast<float>(bar.x + bar.width + std::max(2, bar.width / 2));
  texts.push_back(TextItem{fmt::format("{}{:g}°", panel.colour_scale_saturated ? "≥" : "", panel.colour_scale_deg), x, static_cast<float>(bar.y) - 0.2f * static_cast<float>(px), px});
  texts.push_back(TextItem{"0°", x, static_cast<float>(bar.y + bar.height) - 0.95f * static_cast<float>(px), px});
}

// The error-over-time strip: its quantity named at the top left, degree ticks up
// the left, time ticks in seconds along the bottom, a line (or a per-column min/max
// band, when frames outnumber the columns) per series, keys ticked, the cursor.
void Renderer::Impl::draw_strip(const ErrorStrip& strip, const Rect& r, int width, int height) {
  gl.Enable(GL_SCISSOR_TEST);
  scissor(r, height);
  gl.ClearColor(kTitleStrip[0], kTitleStrip[1], kTitleStrip[2], 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Disable(GL_SCISSOR_TEST);
  const std::size_t n = strip.lines.empty() ? 0 : strip.lines.front().deg.size();
  if (n == 0) return;
  const int px = std::clamp(r.height / 6, 8, 13);
  const double scale = strip.scale_deg > 0.0 ? strip.scale_deg : 1.0;
  bool saturated = false;
  for (const StripLine& line : strip.lines)
    for (float v : line.deg) saturated = saturated || v > scale;
  const std::vector<double> degree_ticks = axis_ticks(0.0, scale);
  auto degree_text = [&](double v) { return fmt::format("{}{:g}°", saturated && v == degree_ticks.back() ? "≥" : "", v); };
  float label_w = 0.0f;
  for (double v : degree_ticks) label_w = std::max(label_w, text_width(degree_text(v))(px));
  const float pad = 4.0f;
  const float x0 = static_cast<float>(r.x) + label_w + 2.0f * pad, x1 = static_cast<float>(r.x + r.width) - 2.0f * pad;
  const float y0 = static_cast<float>(r.y) + 1.35f * static_cast<float>(px) + pad;
  const float y1 = static_cast<float>(r.y + r.height) - 1.35f * static_cast<float>(px) - pad;
  if (!(x1 > x0 + 8.0f) || !(y1 > y0 + 4.0f)) return;
  auto x_at = [&](double i) { return n > 1 ? x0 + (x1 - x0) * static_cast<float>(i / static_cast<double>(n - 1)) : 0.5f * (x0 + x1); };
  auto y_at = [&](double v) { return y1 - static_cast<float>(std::clamp(std::isfinite(v) ? v / scale : 0.0, 0.0, 1.0)) * (y1 - y0); };
  LineList lines;
  // A plot too low for every label keeps the bottom's and the top's.
  const bool every_label = y1 - y0 >= 1.1f * static_cast<float>(px) * static_cast<float>(degree_ticks.size() - 1);
  for (double v : degree_ticks) {
    pixel_line(lines, x0, y_at(v), x1, y_at(v), v == 0.0 ? kStripAxis : kStripGrid);
    if (!every_label && v != 0.0 && v != degree_ticks.back()) continue;
    texts.push_back(TextItem{degree_text(v), static_cast<float>(r.x) + pad + label_w - text_width(degree_text(v))(px),
                             y_at(v) - 0.6f * static_cast<float>(px), px});
  }
  const double t0 = strip.start_s, t1 = std::max(strip.end_s, strip.start_s);
  auto x_of_time = [&](double t) { return t1 > t0 ? x0 + (x1 - x0) * static_cast<float>((t - t0) / (t1 - t0)) : x0; };
  for (double t : axis_ticks(t0, t1)) {
    pixel_line(lines, x_of_time(t), y1, x_of_time(t), y1 + 3.0f, kStripAxis);
    const std::string label = fmt::format("{:g} s", t);
    const float w = text_width(label)(px);
    const float x = std::clamp(x_of_time(t) - 0.5f * w, static_cast<float>(r.x), static_cast<float>(r.x + r.width) - w);
    texts.push_back(TextItem{label, x, y1 + 3.0f, px});
  }
  const auto columns = static_cast<std::size_t>(std::max(1.0f, x1 - x0));
  if (strip.keys.size() * 3 <= columns)  // denser keys would fill the axis
    for (std::size_t k : strip.keys)
      if (k < n) pixel_line(lines, x_at(static_cast<double>(k)), y1, x_at(static_cast<double>(k)), y1 - 4.0f, kStripKey);
  for (const StripLine& line : strip.lines) {
    if (line.deg.size() != n) continue;
    const float rgba[4] = {line.colour[0], line.colour[1], line.colour[2], line.alpha};
    if (n <= columns) {
      for (std::size_t i = 0; i + 1 < n; ++i)
        pixel_line(lines, x_at(static_cast<double>(i)), y_at(line.deg[i]), x_at(static_cast<double>(i + 1)),
                   y_at(line.deg[i + 1]), rgba);
      continue;
    }
    // More frames than columns: each column's min…max as a band, its max joined up.
    const float band[4] = {line.colour[0], line.colour[1], line.colour[2], 0.45f * line.alpha};
    float previous_x = 0.0f, previous_top = 0.0f;
    for (std::size_t c = 0; c < columns; ++c) {
      const std::size_t a = c * n / columns, b = std::max(a + 1, (c + 1) * n / columns);
      const auto [lo, hi] = std::minmax_element(line.deg.begin() + static_cast<std::ptrdiff_t>(a),
                                                line.deg.begin() + static_cast<std::ptrdiff_t>(std::min(b, n)));
      const float x = x0 + static_cast<float>(c) + 0.5f, top = y_at(*hi);
      pixel_line(lines, x, y_at(*lo), x, top, band);
      if (c > 0) pixel_line(lines, previous_x, previous_top, x, top, rgba);
      previous_x = x;
      previous_top = top;
    }
  }
  if (strip.cursor < n) {
    const float x = std::floor(x_at(static_cast<double>(strip.cursor))) + 0.5f;  // crisp: one column
    pixel_line(lines, x, y0 - 2.0f, x, y1, kStripCursor);
  }
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.Viewport(0, 0, width, height);
  draw_lines(lines, pixel_space(width, height));
  gl.Disable(GL_BLEND);
  gl.Enable(GL_DEPTH_TEST);
  texts.push_back(TextItem{strip.quantity, x0, static_cast<float>(r.y) + 2.0f,
                           fitting_height(text_width(strip.quantity), px, x1 - x0)});
}

// The legend at the top right of the figure: a swatch and a line of text for the
// ghost and for each figure, in their colours.
void Renderer::Impl::draw_legend(const Panel& panel, const Rect& figure, int width, int height) {
  std::vector<std::pair<std::string, std::array<float, 4>>> entries;
  if (!panel.ghost_legend.empty()) entries.push_back({panel.ghost_legend, {kGhostSwatch[0], kGhostSwatch[1], kGhostSwatch[2], 1.0f}});
  for (const Figure& f : panel.figures)
    if (!f.legend.empty()) entries.push_back({f.legend, {f.colour[0], f.colour[1], f.colour[2], 1.0f}});
  if (entries.empty()) return;
  const int px = std::max(8, corner_text_height(height) * 9 / 10);
  const float line = 1.3f * static_cast<float>(px), swatch = 1.6f * static_cast<float>(px);
  const float pad = static_cast<float>(corner_text_pad(height));
  float text_w = 0.0f;
  for (const auto& e : entries) text_w = std::max(text_w, text_width(e.first)(px));
  const float x = static_cast<float>(figure.x + figure.width) - pad - text_w - swatch - pad;
  LineList lines;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const float top = static_cast<float>(figure.y) + pad + line * static_cast<float>(i);
    const float mid = top + 0.55f * static_cast<float>(px);
    for (float dy : {-1.0f, 0.0f, 1.0f}) pixel_line(lines, x, mid + dy, x + swatch, mid + dy, entries[i].second.data());
    texts.push_back(TextItem{entries[i].first, x + swatch + pad, top, px, entries[i].second});
  }
  gl.Disable(GL_DEPTH_TEST);
  gl.Viewport(0, 0, width, height);
  draw_lines(lines, pixel_space(width, height));
  gl.Enable(GL_DEPTH_TEST);
}

// `panel.joint_label` next to its joint of the pose, with a short leader line
// (none when the joint is out of view), kept inside the figure.
void Renderer::Impl::label_joint(const Panel& panel, const Camera& camera, const Rect& figure, int width, int height) {
  const auto j = static_cast<std::size_t>(panel.label_joint);
  const auto figure_index = static_cast<std::size_t>(panel.label_figure);
  const WorldPose& pose = panel.label_figure >= 0 && figure_index < panel.figures.size() ? panel.figures[figure_index].pose
                                                                                          : panel.pose;
  if (panel.label_joint < 0 || j >= pose.position.size() || panel.joint_label.empty()) return;
  const Eigen::Vector4d clip = camera.projection() * camera.view() * pose.position[j].homogeneous();
  if (!(clip.w() > 0.0)) return;
  const double px_x = figure.x + (clip.x() / clip.w() + 1.0) * 0.5 * figure.width;
  const double px_y = figure.y + (1.0 - clip.y() / clip.w()) * 0.5 * figure.height;
  if (!std::isfinite(px_x) || !std::isfinite(px_y)) return;
  const int ph = std::clamp(static_cast<int>(std::lround(0.04 * height)), 9, 15);
  const float text_w = text_width(panel.joint_label)(ph);
  const float gap = 1.2f * static_cast<float>(ph);
  float x = static_cast<float>(px_x) + gap, top = static_cast<float>(px_y) - gap - static_cast<float>(ph);
  if (x + text_w > static_cast<float>(figure.x + figure.width) - 2.0f) x = static_cast<float>(px_x) - gap - text_w;
  x = std::clamp(x, static_cast<float>(figure.x) + 2.0f, std::max(static_cast<float>(figure.x) + 2.0f, static_cast<float>(figure.x + figure.width) - text_w - 2.0f));
  top = std::clamp(top, static_cast<float>(figure.y) + 2.0f, static_cast<float>(figure.y + figure.height - ph) - 2.0f);
  texts.push_back(TextItem{panel.joint_label, x, top, ph});
  // A leader to the joint where it is in view (a focus view may leave it out).
  if (px_x < figure.x || px_x > figure.x + figure.width || px_y < figure.y || px_y > figure.y + figure.height) return;
  LineList lines;
  const float ly = top + static_cast<float>(ph);
  const float lx = x < static_cast<float>(px_x) ? x + text_w : x;
  pixel_line(lines, static_cast<float>(px_x), static_cast<float>(px_y), lx, ly, kLeader);
  gl.Disable(GL_DEPTH_TEST);
  gl.Viewport(0, 0, width, height);
  draw_lines(lines, pixel_space(width, height));
  gl.Enable(GL_DEPTH_TEST);
}

}  // namespace rotinterp::render
