// The renderer's inside (Renderer::Impl), shared by its three rooms: renderer_gl.cpp
// (GL programs, meshes, atlases, framebuffers and draw calls), renderer_overlays.cpp
// (trail inset, colour bar, error strip, joint label) and renderer.cpp (a panel, the
// public calls).
#pragma once

#include "rotinterp/render/renderer.h"

#include "font.h"
#include "gl_api.h"
#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/geometry.h"
#include "rotinterp/render/layout.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp::render {

using detail::FontAtlas;
using detail::FontFile;
using detail::GLApi;

// ---- style (all colours linear 0…1) ------------------------------------------
inline constexpr float kBackground[3] = {0.155f, 0.165f, 0.185f};
inline constexpr float kTitleStrip[3] = {0.095f, 0.100f, 0.115f};
inline constexpr float kStripAxis[4] = {0.55f, 0.58f, 0.64f, 1.0f};
inline constexpr float kStripGrid[4] = {0.26f, 0.27f, 0.30f, 1.0f};
// The ghost's colour in a legend: the pale ghost as it shows over the background.
inline constexpr float kGhostSwatch[3] = {0.62f, 0.64f, 0.68f};
inline constexpr float kStripKey[4] = {0.60f, 0.62f, 0.66f, 1.0f};
inline constexpr float kStripCursor[4] = {0.98f, 0.62f, 0.20f, 1.0f};
inline constexpr float kLeader[4] = {0.93f, 0.93f, 0.93f, 0.9f};
// Lighting kept on error-coloured bones (1 = the full shading of method colours).
inline constexpr float kErrorShade = 0.35f;

// ---- GL meshes: the unit meshes of geometry.h with a buffer of instances ------

struct Mesh {
  GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
  GLsizei index_count = 0;
};

inline Eigen::Matrix4f to_float(const Eigen::Matrix4d& m) { return m.cast<float>(); }

struct Renderer::Impl {
  std::unique_ptr<GLContext> context;
  GLApi gl;
  Scene scene;
  int samples = 1;

  GLuint mesh_program = 0, line_program = 0, text_program = 0;
  GLint mesh_view_projection = -1, mesh_light = -1, mesh_eye = -1, mesh_shade = -1;
  GLint line_view_projection = -1;
  GLint text_viewport = -1, text_colour = -1, text_atlas = -1;
  // Two levels of detail: coarse meshes for bones a few pixels thick (most of the
  // time; llvmpipe's vertex work is single-threaded), fine ones for close-ups.
  Mesh cylinder[2], sphere[2];
  int detail = 0;  // the level drawn now
  GLuint line_vao = 0, line_vbo = 0;
  GLuint text_vao = 0, text_vbo = 0;

  std::shared_ptr<const FontFile> font;
  struct GLAtlas {
    FontAtlas atlas;
    GLuint texture = 0;
  };
  std::map<int, GLAtlas> atlases;

  GLuint msaa_fbo = 0, msaa_colour = 0, msaa_depth = 0, resolve_fbo = 0, resolve_colour = 0;
  int fbo_width = 0, fbo_height = 0;
  std::vector<std::uint8_t> readback;

  LineList grid;    // world space
  LineList sphere_lines;
  Batch solid, translucent;
  std::vector<TextItem> texts;

  ~Impl();

  // ---- setup (renderer_gl.cpp) ----

  Result<GLuint> compile(const char* vertex, const char* fragment, const char* name);
  void make_mesh(Mesh& mesh, const MeshData& data);
  void make_dynamic(GLuint& vao, GLuint& vbo, int position_size, int second_size);
  Status setup();
  Error gl_error(const char* where, GLenum code) const;
  const GLAtlas& atlas(int pixel_height);

  // ---- framebuffers and draw calls (renderer_gl.cpp) ----

  void release_framebuffers();
  Status ensure_framebuffers(int width, int height);
  void draw_lines(const std::vector<float>& lines, const Eigen::Matrix4f& view_projection);
  void draw_mesh(const Mesh& mesh, const std::vector<Instance>& instances);

  // `radius` (world units) at the target seen from `camera` in a viewport
  // `viewport_height` pixels high picks the level of detail: fine from 6 px.
  void use_mesh_program(const Camera& camera, double radius, int viewport_height);
  void draw_opaque(const Batch& b);

  // Only the front-most surface of the batch, blended once: a depth-only pass, then
  // a colour pass that passes where the depth equals the stored one. Opaque things
  // drawn before stay in front where they are nearer.
  void draw_translucent(const Batch& b);
  void draw_texts(int width, int height);

  // The width of `text` at a pixel height, in the font drawn.
  TextWidth text_width(const std::string& text);

  // A viewport and scissor box at `r` (y downwards) of a panel `height` pixels high.
  void viewport(const Rect& r, int height) { gl.Viewport(r.x, height - (r.y + r.height), r.width, r.height); }
  void scissor(const Rect& r, int height) { gl.Scissor(r.x, height - (r.y + r.height), r.width, r.height); }

  void read_panel(int width, int height, Image& image, const Rect& rect);

  // ---- over the figure (renderer_overlays.cpp) ----

  void draw_trail(const Panel& panel, const Trail& trail, const Rect& inset, int height);

  // A vertical viridis bar from 0 (bottom) to the panel's scale (top), one line
  // per row, labelled in degrees at both ends.
  void draw_colour_bar(const Panel& panel, const Rect& bar, int width, int height);

  // The error-over-time strip: its quantity named at the top left, degree ticks up
  // the left, time ticks in seconds along the bottom, a line (or a per-column
  // min/max band, when frames outnumber the columns) per series, keys, the cursor.
  void draw_strip(const ErrorStrip& strip, const Rect& r, int width, int height);

  // The legend at the top right of the figure: a swatch and a line of text for the
  // ghost and for each figure, in their colours.
  void draw_legend(const Panel& panel, const Rect& figure, int width, int height);

  // `panel.joint_label` next to its joint of the pose, with a short leader line
  // (none when the joint is out of view), kept inside the figure.
  void label_joint(const Panel& panel, const Camera& camera, const Rect& figure, int width, int height);

  // ---- a panel (renderer.cpp) ----

  Status draw_panel(const Panel& panel, int width, int height);
};

}  // namespace rotinterp::render
