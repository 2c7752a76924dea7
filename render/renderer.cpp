#include "rotinterp/render/renderer.h"

#include "font.h"
#include "gl_api.h"
#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/geometry.h"
#include "rotinterp/render/layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace rotinterp::render {

using detail::FontAtlas;
using detail::FontFile;
using detail::GLApi;

namespace {

// ---- shaders -----------------------------------------------------------------

// Instanced meshes (bone cylinders, joint spheres) with simple lighting: a
// hemisphere ambient, one directional light and a little Blinn–Phong specular.
constexpr const char* kMeshVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in mat4 i_model;
layout(location = 6) in vec4 i_color;
uniform mat4 u_view_projection;
out vec3 v_normal;
out vec3 v_world;
out vec4 v_color;
invariant gl_Position;
void main() {
  vec4 world = i_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  // Meshes scale uniformly across their normals (spheres; cylinders radially), so
  // the model matrix maps normals to normal directions.
  v_normal = mat3(i_model) * a_normal;
  v_color = i_color;
  gl_Position = u_view_projection * world;
}
)";

constexpr const char* kMeshFragment = R"(#version 330 core
in vec3 v_normal;
in vec3 v_world;
in vec4 v_color;
uniform vec3 u_light;
uniform vec3 u_eye;
uniform float u_shade;
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(u_eye - v_world);
  float diffuse = max(dot(n, u_light), 0.0);
  float hemisphere = 0.5 + 0.5 * n.y;
  vec3 h = normalize(u_light + v);
  float specular = pow(max(dot(n, h), 0.0), 40.0) * 0.25;
  // u_shade < 1 flattens the lighting towards the plain colour (error colours stay
  // readable against their colour bar).
  float light = mix(1.0, 0.28 + 0.17 * hemisphere + 0.62 * diffuse, u_shade);
  vec3 rgb = v_color.rgb * light + vec3(specular * u_shade);
  o_color = vec4(min(rgb, vec3(1.0)), v_color.a);
}
)";

constexpr const char* kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_projection;
out vec4 v_color;
void main() {
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

constexpr const char* kLineFragment = R"(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";

// Text: quads in pixels (y downwards), coverage from the glyph atlas.
constexpr const char* kTextVertex = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
uniform vec2 u_viewport;
out vec2 v_uv;
void main() {
  v_uv = a_uv;
  gl_Position = vec4(a_position.x / u_viewport.x * 2.0 - 1.0, 1.0 - a_position.y / u_viewport.y * 2.0, 0.0, 1.0);
}
)";

constexpr const char* kTextFragment = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_atlas;
uniform vec4 u_color;
out vec4 o_color;
void main() { o_color = vec4(u_color.rgb, u_color.a * texture(u_atlas, v_uv).r); }
)";

// ---- style (all colours linear 0…1) ------------------------------------------
constexpr float kBackground[3] = {0.155f, 0.165f, 0.185f};
constexpr float kTitleStrip[3] = {0.095f, 0.100f, 0.115f};
constexpr float kTitleText[4] = {0.93f, 0.93f, 0.93f, 1.0f};
constexpr float kStripMax[4] = {0.93f, 0.93f, 0.93f, 1.0f};
constexpr float kStripMean[4] = {0.55f, 0.58f, 0.64f, 1.0f};
constexpr float kStripKey[4] = {0.60f, 0.62f, 0.66f, 1.0f};
constexpr float kStripCursor[4] = {0.98f, 0.62f, 0.20f, 1.0f};
constexpr float kLeader[4] = {0.93f, 0.93f, 0.93f, 0.9f};
// Lighting kept on error-coloured bones (1 = the full shading of method colours).
constexpr float kErrorShade = 0.35f;

// ---- GL meshes: the unit meshes of geometry.h with a buffer of instances ------

struct Mesh {
  GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
  GLsizei index_count = 0;
};

Eigen::Matrix4f to_float(const Eigen::Matrix4d& m) { return m.cast<float>(); }

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

}  // namespace

struct Renderer::Impl {
  std::unique_ptr<GLContext> context;
  GLApi gl;
  Scene scene;
  int samples = 1;

  GLuint mesh_program = 0, line_program = 0, text_program = 0;
  GLint mesh_view_projection = -1, mesh_light = -1, mesh_eye = -1, mesh_shade = -1;
  GLint line_view_projection = -1;
  GLint text_viewport = -1, text_color = -1, text_atlas = -1;
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

  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0, resolve_fbo = 0, resolve_color = 0;
  int fbo_width = 0, fbo_height = 0;
  std::vector<std::uint8_t> readback;

  LineList grid;    // world space
  LineList sphere_lines;
  Batch solid, translucent;
  std::vector<TextItem> texts;

  ~Impl() {
    if (!gl.DeleteProgram || !context->make_current()) return;  // GL never loaded, or the context is gone
    for (GLuint p : {mesh_program, line_program, text_program})
      if (p) gl.DeleteProgram(p);
    for (Mesh* m : {&cylinder[0], &cylinder[1], &sphere[0], &sphere[1]}) {
      gl.DeleteVertexArrays(1, &m->vao);
      GLuint buffers[] = {m->vertices, m->indices, m->instances};
      gl.DeleteBuffers(3, buffers);
    }
    GLuint vaos[] = {line_vao, text_vao};
    gl.DeleteVertexArrays(2, vaos);
    GLuint buffers[] = {line_vbo, text_vbo};
    gl.DeleteBuffers(2, buffers);
    for (auto& [size, a] : atlases) gl.DeleteTextures(1, &a.texture);
    release_framebuffers();
  }

  // ---- setup ---------------------------------------------------------------------

  Result<GLuint> compile(const char* vertex, const char* fragment, const char* name) {
    GLuint shaders[2] = {gl.CreateShader(GL_VERTEX_SHADER), gl.CreateShader(GL_FRAGMENT_SHADER)};
    const char* sources[2] = {vertex, fragment};
    for (int i = 0; i < 2; ++i) {
      gl.ShaderSource(shaders[i], 1, &sources[i], nullptr);
      gl.CompileShader(shaders[i]);
      GLint ok = 0;
      gl.GetShaderiv(shaders[i], GL_COMPILE_STATUS, &ok);
      if (!ok) {
        char log[1024] = {0};
        gl.GetShaderInfoLog(shaders[i], sizeof log, nullptr, log);
        for (char& c : log)
          if (c == '\n') c = ' ';
        return make_error(std::string("render: the ") + name + " shader does not compile: " + log);
      }
    }
    GLuint program = gl.CreateProgram();
    gl.AttachShader(program, shaders[0]);
    gl.AttachShader(program, shaders[1]);
    gl.LinkProgram(program);
    gl.DeleteShader(shaders[0]);
    gl.DeleteShader(shaders[1]);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[1024] = {0};
      gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
      return make_error(std::string("render: the ") + name + " program does not link: " + log);
    }
    return program;
  }

  void make_mesh(Mesh& mesh, const MeshData& data) {
    const std::vector<float>& v = data.vertices;
    const std::vector<unsigned>& idx = data.indices;
    gl.GenVertexArrays(1, &mesh.vao);
    gl.BindVertexArray(mesh.vao);
    gl.GenBuffers(1, &mesh.vertices);
    gl.BindBuffer(GL_ARRAY_BUFFER, mesh.vertices);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STATIC_DRAW);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    gl.GenBuffers(1, &mesh.indices);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(unsigned)), idx.data(),
                  GL_STATIC_DRAW);
    mesh.index_count = static_cast<GLsizei>(idx.size());
    gl.GenBuffers(1, &mesh.instances);
    gl.BindBuffer(GL_ARRAY_BUFFER, mesh.instances);
    for (GLuint column = 0; column < 4; ++column) {
      gl.EnableVertexAttribArray(2 + column);
      gl.VertexAttribPointer(2 + column, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                             reinterpret_cast<void*>(column * 4 * sizeof(float)));
      gl.VertexAttribDivisor(2 + column, 1);
    }
    gl.EnableVertexAttribArray(6);
    gl.VertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, sizeof(Instance), reinterpret_cast<void*>(offsetof(Instance, color)));
    gl.VertexAttribDivisor(6, 1);
    gl.BindVertexArray(0);
  }

  void make_dynamic(GLuint& vao, GLuint& vbo, int position_size, int second_size) {
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.GenBuffers(1, &vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    const GLsizei stride = static_cast<GLsizei>((position_size + second_size) * sizeof(float));
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, position_size, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, second_size, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(static_cast<std::size_t>(position_size) * sizeof(float)));
    gl.BindVertexArray(0);
  }

  Status setup() {
    if (Status s = gl.load(*context); !s) return s;
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 3 || (major == 3 && minor < 3))
      return make_error(std::string(backend_name(context->backend())) + ": OpenGL " + std::to_string(major) + "." +
                        std::to_string(minor) + " is too old (3.3 core needed)");
    GLint max_samples = 1;
    gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = std::clamp(max_samples, 1, kSamples);

    auto mesh = compile(kMeshVertex, kMeshFragment, "mesh");
    if (!mesh) return mesh.failure();
    mesh_program = *mesh;
    auto line = compile(kLineVertex, kLineFragment, "line");
    if (!line) return line.failure();
    line_program = *line;
    auto text = compile(kTextVertex, kTextFragment, "text");
    if (!text) return text.failure();
    text_program = *text;
    mesh_view_projection = gl.GetUniformLocation(mesh_program, "u_view_projection");
    mesh_light = gl.GetUniformLocation(mesh_program, "u_light");
    mesh_eye = gl.GetUniformLocation(mesh_program, "u_eye");
    mesh_shade = gl.GetUniformLocation(mesh_program, "u_shade");
    line_view_projection = gl.GetUniformLocation(line_program, "u_view_projection");
    text_viewport = gl.GetUniformLocation(text_program, "u_viewport");
    text_color = gl.GetUniformLocation(text_program, "u_color");
    text_atlas = gl.GetUniformLocation(text_program, "u_atlas");

    for (int level = 0; level < 2; ++level) {
      make_mesh(cylinder[level], cylinder_mesh(level ? 24 : 10));
      make_mesh(sphere[level], sphere_mesh(level ? 24 : 10, level ? 14 : 6));
    }
    make_dynamic(line_vao, line_vbo, 3, 4);
    make_dynamic(text_vao, text_vbo, 2, 2);

    auto f = FontFile::load(ROTINTERP_FONT_PATH);
    if (!f) return f.failure();
    font = *f;

    grid = grid_lines(scene.bounds);
    sphere_lines = sphere_wireframe();
    if (GLenum e = gl.GetError(); e != GL_NO_ERROR) return gl_error("setup", e);
    return Ok{};
  }

  Error gl_error(const char* where, GLenum code) const {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", code);
    return make_error(std::string(backend_name(context->backend())) + ": OpenGL error " + hex + " during " + where);
  }

  const GLAtlas& atlas(int pixel_height) {
    auto it = atlases.find(pixel_height);
    if (it != atlases.end()) return it->second;
    auto built = FontAtlas::build(font, pixel_height);
    ROTINTERP_ASSERT(built.ok());  // only fails past 4096² atlases, far above any title size
    GLAtlas a{std::move(built).value(), 0};
    gl.GenTextures(1, &a.texture);
    gl.BindTexture(GL_TEXTURE_2D, a.texture);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, a.atlas.width(), a.atlas.height(), 0, GL_RED, GL_UNSIGNED_BYTE,
                  a.atlas.bitmap().data());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return atlases.emplace(pixel_height, std::move(a)).first->second;
  }

  // ---- framebuffers --------------------------------------------------------------

  void release_framebuffers() {
    if (msaa_fbo) {
      GLuint fbos[] = {msaa_fbo, resolve_fbo};
      gl.DeleteFramebuffers(2, fbos);
      GLuint rbs[] = {msaa_color, msaa_depth, resolve_color};
      gl.DeleteRenderbuffers(3, rbs);
    }
    msaa_fbo = resolve_fbo = msaa_color = msaa_depth = resolve_color = 0;
    fbo_width = fbo_height = 0;
  }

  Status ensure_framebuffers(int width, int height) {
    if (width == fbo_width && height == fbo_height) return Ok{};
    release_framebuffers();
    gl.GenFramebuffers(1, &msaa_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
    gl.GenRenderbuffers(1, &msaa_color);
    gl.BindRenderbuffer(GL_RENDERBUFFER, msaa_color);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color);
    gl.GenRenderbuffers(1, &msaa_depth);
    gl.BindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      return make_error(std::string(backend_name(context->backend())) + ": cannot make a " + std::to_string(width) +
                        "×" + std::to_string(height) + " multisampled framebuffer");
    gl.GenFramebuffers(1, &resolve_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo);
    gl.GenRenderbuffers(1, &resolve_color);
    gl.BindRenderbuffer(GL_RENDERBUFFER, resolve_color);
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      return make_error(std::string(backend_name(context->backend())) + ": cannot make a " + std::to_string(width) +
                        "×" + std::to_string(height) + " framebuffer");
    fbo_width = width;
    fbo_height = height;
    return Ok{};
  }

  // ---- drawing ---------------------------------------------------------------------

  void draw_lines(const std::vector<float>& lines, const Eigen::Matrix4f& view_projection) {
    if (lines.empty()) return;
    gl.UseProgram(line_program);
    gl.UniformMatrix4fv(line_view_projection, 1, GL_FALSE, view_projection.data());
    gl.BindVertexArray(line_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(float)), lines.data(), GL_STREAM_DRAW);
    gl.DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size() / 7));
  }

  void draw_mesh(const Mesh& mesh, const std::vector<Instance>& instances) {
    if (instances.empty()) return;
    gl.BindVertexArray(mesh.vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, mesh.instances);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances.size() * sizeof(Instance)), instances.data(),
                  GL_STREAM_DRAW);
    gl.DrawElementsInstanced(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr,
                             static_cast<GLsizei>(instances.size()));
  }

  // `radius` (world units) at the target seen from `camera` in a viewport
  // `viewport_height` pixels high picks the level of detail: fine from 6 px.
  void use_mesh_program(const Camera& camera, double radius, int viewport_height) {
    detail = pixels_at_target(camera, radius, viewport_height) >= 6.0 ? 1 : 0;
    const Eigen::Matrix4f vp = to_float(camera.projection() * camera.view());
    const Vec3 back = (camera.eye - camera.target).normalized();
    const Vec3 right = camera.up.cross(back).normalized();
    const Vec3 up = back.cross(right);
    const Vec3 light = (0.35 * right + 0.85 * up + 0.45 * back).normalized();
    gl.UseProgram(mesh_program);
    gl.UniformMatrix4fv(mesh_view_projection, 1, GL_FALSE, vp.data());
    gl.Uniform3f(mesh_light, static_cast<float>(light.x()), static_cast<float>(light.y()), static_cast<float>(light.z()));
    gl.Uniform3f(mesh_eye, static_cast<float>(camera.eye.x()), static_cast<float>(camera.eye.y()),
                 static_cast<float>(camera.eye.z()));
    gl.Uniform1f(mesh_shade, 1.0f);
  }

  void draw_opaque(const Batch& b) {
    gl.Disable(GL_BLEND);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
    draw_mesh(cylinder[detail], b.cylinders);
    draw_mesh(sphere[detail], b.spheres);
  }

  // Only the front-most surface of the batch, blended once: a depth-only pass, then
  // a colour pass that passes where the depth equals the stored one. Opaque things
  // drawn before stay in front where they are nearer.
  void draw_translucent(const Batch& b) {
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
    gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    draw_mesh(cylinder[detail], b.cylinders);
    draw_mesh(sphere[detail], b.spheres);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.DepthMask(GL_FALSE);
    gl.DepthFunc(GL_LEQUAL);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    draw_mesh(cylinder[detail], b.cylinders);
    draw_mesh(sphere[detail], b.spheres);
    gl.Disable(GL_BLEND);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(GL_LESS);
  }

  void draw_texts(int width, int height) {
    if (texts.empty()) return;
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_DEPTH_TEST);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl.UseProgram(text_program);
    gl.Uniform1i(text_atlas, 0);
    gl.Uniform2f(text_viewport, static_cast<float>(width), static_cast<float>(height));
    gl.Uniform4f(text_color, kTitleText[0], kTitleText[1], kTitleText[2], kTitleText[3]);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindVertexArray(text_vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, text_vbo);
    std::vector<float> v;
    for (const TextItem& t : texts) {
      const GLAtlas& a = atlas(t.pixel_height);
      v.clear();
      for (const auto& q : a.atlas.layout(t.text, t.x, t.top + a.atlas.ascent()))
        v.insert(v.end(), {q.x0, q.y0, q.s0, q.t0, q.x1, q.y0, q.s1, q.t0, q.x1, q.y1, q.s1, q.t1,
                           q.x0, q.y0, q.s0, q.t0, q.x1, q.y1, q.s1, q.t1, q.x0, q.y1, q.s0, q.t1});
      if (v.empty()) continue;
      gl.BindTexture(GL_TEXTURE_2D, a.texture);
      gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STREAM_DRAW);
      gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size() / 4));
    }
    gl.Disable(GL_BLEND);
    gl.Enable(GL_DEPTH_TEST);
    texts.clear();
  }

  // The width of `text` at a pixel height, in the font drawn.
  TextWidth text_width(const std::string& text) {
    return [this, &text](int pixel_height) { return atlas(pixel_height).atlas.text_width(text); };
  }

  // A viewport and scissor box at `r` (y downwards) of a panel `height` pixels high.
  void viewport(const Rect& r, int height) { gl.Viewport(r.x, height - (r.y + r.height), r.width, r.height); }
  void scissor(const Rect& r, int height) { gl.Scissor(r.x, height - (r.y + r.height), r.width, r.height); }

  void draw_trail(const Panel& panel, const Trail& trail, const Rect& inset, int height) {
    gl.Enable(GL_SCISSOR_TEST);
    scissor(inset, height);
    gl.ClearColor(kInsetBackground[0], kInsetBackground[1], kInsetBackground[2], 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    viewport(inset, height);
    const TrailView view = trail_view(trail.reference, trail.method, scene.view);
    draw_lines(sphere_lines, to_float(view.camera.projection() * view.camera.view()));
    use_mesh_program(view.camera, view.zoom * kTrailReferenceRadius, inset.height);
    trail_figure(trail, panel.color, view.zoom, solid, translucent);
    draw_opaque(solid);
    draw_translucent(translucent);
    gl.Disable(GL_SCISSOR_TEST);
    if (!trail.label.empty()) texts.push_back(inset_label(trail.label, inset, text_width(trail.label)));
  }

  // A vertical viridis bar from 0 (bottom) to the panel's scale (top), one line
  // per row, labelled in degrees at both ends.
  void draw_colour_bar(const Panel& panel, const Rect& bar, int width, int height) {
    LineList lines;
    for (int row = 0; row < bar.height; ++row) {
      const Color c = viridis(static_cast<double>(bar.height - 1 - row) / std::max(1, bar.height - 1));
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
  void draw_strip(const ErrorStrip& strip, const Rect& r, int width, int height) {
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
  void label_joint(const Panel& panel, const Camera& camera, const Rect& figure, int width, int height) {
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

  Status draw_panel(const Panel& panel, int width, int height) {
    // Room for both corner lines whether drawn or not: a frame's panel and its sheet
    // cell (no corner line) frame the figure alike.
    const PanelLayout layout = panel_layout(width, height, panel.trail && !panel.trail->reference.empty(),
                                            panel.strip != nullptr, panel.colour_scale_deg > 0.0, 2);
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
    const Camera camera = frame_bounds(box, static_cast<double>(figure.width) / figure.height, scene.view);
    const Eigen::Matrix4f view_projection = to_float(camera.projection() * camera.view());
    if (panel.view)
      draw_lines(grid_lines(ground_under(*panel.view, scene.bounds.empty() ? box.min.y() : scene.bounds.min.y())),
                 view_projection);
    else
      draw_lines(grid, view_projection);
    use_mesh_program(camera, scene.bone_radius, figure.height);
    panel_figure(scene, panel, solid, translucent);
    if (!panel.joint_colors.empty()) gl.Uniform1f(mesh_shade, kErrorShade);
    draw_opaque(solid);
    gl.Uniform1f(mesh_shade, 1.0f);
    draw_translucent(translucent);
    label_joint(panel, camera, figure, width, height);
    if (layout.inset.width >= 32) draw_trail(panel, *panel.trail, layout.inset, height);
    if (layout.bar.height > 0) draw_colour_bar(panel, layout.bar, width, height);
    if (layout.strip.height > 0) draw_strip(*panel.strip, layout.strip, width, height);
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
        texts.push_back(TextItem{fmt::format("colours 0-{:g}°, all panels", panel.colour_scale_deg), pad, top, small});
      }
    }

    texts.push_back(title_text(panel.title, layout, width, text_width(panel.title)));
    draw_texts(width, height);
    if (GLenum e = gl.GetError(); e != GL_NO_ERROR) return gl_error("drawing a panel", e);
    return Ok{};
  }

  void read_panel(int width, int height, Image& image, const Rect& rect) {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo);
    gl.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    readback.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, readback.data());
    for (int row = 0; row < height; ++row) {
      const std::uint8_t* src = readback.data() + static_cast<std::size_t>(height - 1 - row) * width * 4;
      std::uint8_t* dst = image.pixel(rect.x, rect.y + row);
      for (int col = 0; col < width; ++col) {
        dst[3 * col + 0] = src[4 * col + 0];
        dst[3 * col + 1] = src[4 * col + 1];
        dst[3 * col + 2] = src[4 * col + 2];
      }
    }
  }
};

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
