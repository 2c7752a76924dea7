// What the renderer draws over a panel's figure: the trail inset, the colour bar,
// the error strip and the joint label.
#include "renderer_impl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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
  texts.push_back(TextItem{fmt::format("{:g}°", panel.colour_scale_deg), x, static_cast<float>(bar.y) - 0.2f * static_cast<float>(px), px});
  texts.push_back(TextItem{"0°", x, static_cast<float>(bar.y + bar.height) - 0.95f * static_cast<float>(px), px});
}

// The error-over-time strip: max (bright) and mean (dim) against frames, keys as
// ticks at the bottom, the cursor at the panel's frame, the scale at the top left.
void Renderer::Impl::draw_strip(const ErrorStrip& strip, const Rect& r, int width, int height) {
  gl.Enable(GL_SCISSOR_TEST);
  scissor(r, height);
  gl.ClearColor(kTitleStrip[0], kTitleStrip[1], kTitleStrip[2], 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Disable(GL_SCISSOR_TEST);
  const std::size_t n = strip.max_deg.size();
  if (n == 0) return;
  const float pad = static_cast<float>(std::max(3, r.height / 8));
  const float x0 = static_cast<float>(r.x) + pad, x1 = static_cast<float>(r.x + r.width) - pad;
  const float y0 = static_cast<float>(r.y) + pad, y1 = static_cast<float>(r.y + r.height) - pad;
  const double scale = strip.scale_deg > 0.0 ? strip.scale_deg : 1.0;
  auto x_at = [&](std::size_t i) { return n > 1 ? x0 + (x1 - x0) * static_cast<float>(i) / static_cast<float>(n - 1) : 0.5f * (x0 + x1); };
  auto y_at = [&](float v) {
    const double f = std::clamp(std::isfinite(v) ? v / scale : 0.0, 0.0, 1.0);
    return y1 - static_cast<float>(f) * (y1 - y0);
  };
  LineList lines;
  for (std::size_t k : strip.keys)
    if (k < n) pixel_line(lines, x_at(k), y1, x_at(k), y1 + 0.5f * pad, kStripKey);
  for (const auto* series : {&strip.mean_deg, &strip.max_deg}) {
    const float* rgba = series == &strip.max_deg ? kStripMax : kStripMean;
    if (series->size() != n) continue;
    for (std::size_t i = 0; i + 1 < n; ++i)
      pixel_line(lines, x_at(i), y_at((*series)[i]), x_at(i + 1), y_at((*series)[i + 1]), rgba);
  }
  if (strip.cursor < n) pixel_line(lines, x_at(strip.cursor), y0 - 0.5f * pad, x_at(strip.cursor), y1 + 0.5f * pad, kStripCursor);
  gl.Disable(GL_DEPTH_TEST);
  gl.Viewport(0, 0, width, height);
  draw_lines(lines, pixel_space(width, height));
  gl.Enable(GL_DEPTH_TEST);
  const int px = std::clamp(r.height / 4, 8, 14);
  texts.push_back(TextItem{fmt::format("max and mean error, 0-{:g}°", scale), x0 + 2.0f, static_cast<float>(r.y) + 1.0f, px});
}

// `panel.joint_label` next to its joint of the pose, with a short leader line
// (none when the joint is out of view), kept inside the figure.
void Renderer::Impl::label_joint(const Panel& panel, const Camera& camera, const Rect& figure, int width, int height) {
  const auto j = static_cast<std::size_t>(panel.label_joint);
  if (panel.label_joint < 0 || j >= panel.pose.position.size() || panel.joint_label.empty()) return;
  const Eigen::Vector4d clip = camera.projection() * camera.view() * panel.pose.position[j].homogeneous();
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
