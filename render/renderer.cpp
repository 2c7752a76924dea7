// The renderer: a panel drawn (background, ground, figure, overlays, texts) and
// read into the image, and the public calls.
#include "renderer_impl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace rotinterp::render {

namespace {

// The ground under a panel's own view: its horizontal extent grown by half on
// every side (the camera looks down at it, so more ground shows than the box), at
// the height of the scene's ground.
Bounds ground_under(const Bounds& view, double ground_y) {
  const Vec3 grow = 0.5 * view.size();
  Bounds b;
  b.extend(Vec3(view.min.x() - grow.x(), ground_y, view.min.z() - grow.z()));
  b.extend(Vec3(view.max.x() + grow.x(), ground_y, view.max.z() + grow.z()));
  return b;
}

// The layout of a panel: room for both corner lines whether drawn or not, so a
// frame's panel and its sheet cell (no corner line) frame the figure alike.
PanelLayout layout_of(const Panel& panel, int width, int height) {
  return panel_layout(width, height, panel.trail && !panel.trail->reference.empty(), panel.strip != nullptr,
                      panel.colour_scale_deg > 0.0, 2);
}

}  // namespace

PanelCamera panel_camera(const Scene& scene, const Panel& panel, int width, int height) {
  const Rect figure = layout_of(panel, width, height).view;
  const Bounds& box = panel.view ? *panel.view : scene.bounds;
  return PanelCamera{frame_bounds(box, static_cast<double>(figure.width) / figure.height, scene.view), figure};
}

Status Renderer::Impl::draw_panel(const Panel& panel, int width, int height) {
  const PanelLayout layout = layout_of(panel, width, height);
  gl.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  gl.Viewport(0, 0, width, height);
  gl.Disable(GL_SCISSOR_TEST);
  gl.ClearColor(kBackground[0], kBackground[1], kBackground[2], 1.0f);
  gl.ClearDepth(1.0);
  gl.DepthMask(GL_TRUE);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_SCISSOR_TEST);
  scissor(Rect{0, 0, width, layout.title_height}, height);
  gl.ClearColor(kTitleStrip[0], kTitleStrip[1], kTitleStrip[2], 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Disable(GL_SCISSOR_TEST);

  const Rect& figure = layout.view;  // the camera's: below the corner text
  viewport(figure, height);
  gl.Enable(GL_DEPTH_TEST);
  gl.Enable(GL_MULTISAMPLE);
  const Bounds& box = panel.view ? *panel.view : scene.bounds;
  const Camera camera = panel_camera(scene, panel, width, height).camera;
  const Eigen::Matrix4f view_projection = to_float(camera.projection() * camera.view());
  if (panel.view)
    draw_lines(grid_lines(ground_under(*panel.view, scene.bounds.empty() ? box.min.y() : scene.bounds.min.y())),
               view_projection);
  else
    draw_lines(grid, view_projection);
  use_mesh_program(camera, scene.bone_radius, figure.height);
  panel_figure(scene, panel, solid, translucent);
  if (!panel.joint_colours.empty()) gl.Uniform1f(mesh_shade, kErrorShade);
  draw_opaque(solid);
  gl.Uniform1f(mesh_shade, 1.0f);
  draw_translucent(translucent);
  label_joint(panel, camera, figure, width, height);
  if (layout.inset.width >= 32) draw_trail(panel, *panel.trail, layout.inset, height);
  if (layout.bar.height > 0) draw_colour_bar(panel, layout.bar, width, height);
  if (layout.strip.height > 0) draw_strip(*panel.strip, layout.strip, width, height);
  draw_legend(panel, figure, width, height);
  {
    const int ph = corner_text_height(height);
    const float pad = static_cast<float>(corner_text_pad(height));
    float top = static_cast<float>(layout.figure.y) + pad;
    if (!panel.corner.empty()) {
      texts.push_back(TextItem{panel.corner, pad, top, ph});
      top += 1.2f * static_cast<float>(ph);
    }
    if (layout.bar.height > 0) {  // the scale, stated: the same in every panel of the image
      const int small = std::max(8, ph * 4 / 5);
      texts.push_back(TextItem{fmt::format("joint error, colours 0-{}{:g}°, every image", panel.colour_scale_saturated ? "≥" : "",
                                           panel.colour_scale_deg), pad, top, small});
    }
  }

  texts.push_back(title_text(panel.title, layout, width, text_width(panel.title)));
  draw_texts(width, height);
  if (GLenum e = gl.GetError(); e != GL_NO_ERROR) return gl_error("drawing a panel", e);
  return Ok{};
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(std::unique_ptr<GLContext> context, Scene scene) {
  if (!context) return make_error("render: no GL context");
  if (Status s = scene.skeleton.validate(); !s) return s.failure("render: ");
  auto impl = std::make_unique<Impl>();
  impl->context = std::move(context);
  if (!(scene.bone_radius > 0.0) || !std::isfinite(scene.bone_radius))
    scene.bone_radius = scene_bone_radius(scene.skeleton, scene.bounds);
  impl->scene = std::move(scene);
  if (Status s = impl->context->make_current(); !s) return s.failure();
  if (Status s = impl->setup(); !s) return s.failure();
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

const Scene& Renderer::scene() const { return impl_->scene; }
Backend Renderer::backend() const { return impl_->context->backend(); }

std::string Renderer::gl_description() const {
  auto str = [&](GLenum name) {
    const GLubyte* s = impl_->gl.GetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

Status check_image_size(int width, int height, int panels, int columns) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    return make_error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1…" +
                      std::to_string(kMaxImageSide) + " per side");
  if (panels < 1) return make_error("nothing to draw (no panels)");
  if (columns <= 0) columns = automatic_columns(panels, width, height);
  const Rect first = grid_layout(panels, columns, width, height).front();
  if (first.width < kMinPanelWidth || first.height < kMinPanelHeight)
    return make_error("image size " + std::to_string(width) + "x" + std::to_string(height) + " is too small for " +
                      std::to_string(panels) + (panels == 1 ? " panel" : " panels") + " (each needs at least " +
                      std::to_string(kMinPanelWidth) + "x" + std::to_string(kMinPanelHeight) + ")");
  return Ok{};
}

Result<Image> Renderer::render(const std::vector<Panel>& panels, int width, int height, int columns) {
  const int count = static_cast<int>(panels.size());
  if (Status s = check_image_size(width, height, count, columns); !s) return s.failure("render: ");
  if (columns <= 0) columns = automatic_columns(count, width, height);
  const std::vector<Rect> rects = grid_layout(count, columns, width, height);
  const Rect& first = rects.front();
  Impl& m = *impl_;
  if (Status s = m.context->make_current(); !s) return s.failure();
  if (Status s = m.ensure_framebuffers(first.width, first.height); !s) return s.failure();
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = static_cast<std::uint8_t>(std::lround(kBackground[0] * 255));
    image.rgb[i + 1] = static_cast<std::uint8_t>(std::lround(kBackground[1] * 255));
    image.rgb[i + 2] = static_cast<std::uint8_t>(std::lround(kBackground[2] * 255));
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    if (Status s = m.draw_panel(panels[i], first.width, first.height); !s) return s.failure();
    m.read_panel(first.width, first.height, image, rects[i]);
  }
  if (GLenum e = m.gl.GetError(); e != GL_NO_ERROR) return m.gl_error("reading pixels", e);
  return image;
}

}  // namespace rotinterp::render
