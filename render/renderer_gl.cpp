// The renderer's GL side: programs, meshes, glyph atlases, framebuffers, the draw
// calls and the read-back.
#include "renderer_impl.h"
#include "shaders.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>

namespace rotinterp::render {

Renderer::Impl::~Impl() {
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

Result<GLuint> Renderer::Impl::compile(const char* vertex, const char* fragment, const char* name) {
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

void Renderer::Impl::make_mesh(Mesh& mesh, const MeshData& data) {
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
  gl.VertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, sizeof(Instance), reinterpret_cast<void*>(offsetof(Instance, colour)));
  gl.VertexAttribDivisor(6, 1);
  gl.BindVertexArray(0);
}

void Renderer::Impl::make_dynamic(GLuint& vao, GLuint& vbo, int position_size, int second_size) {
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

Status Renderer::Impl::setup() {
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
  text_colour = gl.GetUniformLocation(text_program, "u_color");
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

Error Renderer::Impl::gl_error(const char* where, GLenum code) const {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", code);
  return make_error(std::string(backend_name(context->backend())) + ": OpenGL error " + hex + " during " + where);
}

const Renderer::Impl::GLAtlas& Renderer::Impl::atlas(int pixel_height) {
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

void Renderer::Impl::release_framebuffers() {
  if (msaa_fbo) {
    GLuint fbos[] = {msaa_fbo, resolve_fbo};
    gl.DeleteFramebuffers(2, fbos);
    GLuint rbs[] = {msaa_colour, msaa_depth, resolve_colour};
    gl.DeleteRenderbuffers(3, rbs);
  }
  msaa_fbo = resolve_fbo = msaa_colour = msaa_depth = resolve_colour = 0;
  fbo_width = fbo_height = 0;
}

Status Renderer::Impl::ensure_framebuffers(int width, int height) {
  if (width == fbo_width && height == fbo_height) return Ok{};
  release_framebuffers();
  gl.GenFramebuffers(1, &msaa_fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
  gl.GenRenderbuffers(1, &msaa_colour);
  gl.BindRenderbuffer(GL_RENDERBUFFER, msaa_colour);
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_colour);
  gl.GenRenderbuffers(1, &msaa_depth);
  gl.BindRenderbuffer(GL_RENDERBUFFER, msaa_depth);
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaa_depth);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error(std::string(backend_name(context->backend())) + ": cannot make a " + std::to_string(width) +
                      "×" + std::to_string(height) + " multisampled framebuffer");
  gl.GenFramebuffers(1, &resolve_fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_fbo);
  gl.GenRenderbuffers(1, &resolve_colour);
  gl.BindRenderbuffer(GL_RENDERBUFFER, resolve_colour);
  gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, width, height);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error(std::string(backend_name(context->backend())) + ": cannot make a " + std::to_string(width) +
                      "×" + std::to_string(height) + " framebuffer");
  fbo_width = width;
  fbo_height = height;
  return Ok{};
}

void Renderer::Impl::draw_lines(const std::vector<float>& lines, const Eigen::Matrix4f& view_projection) {
  if (lines.empty()) return;
  gl.UseProgram(line_program);
  gl.UniformMatrix4fv(line_view_projection, 1, GL_FALSE, view_projection.data());
  gl.BindVertexArray(line_vao);
  gl.BindBuffer(GL_ARRAY_BUFFER, line_vbo);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(float)), lines.data(), GL_STREAM_DRAW);
  gl.DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size() / 7));
}

void Renderer::Impl::draw_mesh(const Mesh& mesh, const std::vector<Instance>& instances) {
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
void Renderer::Impl::use_mesh_program(const Camera& camera, double radius, int viewport_height) {
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

void Renderer::Impl::draw_opaque(const Batch& b) {
  gl.Disable(GL_BLEND);
  gl.DepthMask(GL_TRUE);
  gl.DepthFunc(GL_LESS);
  draw_mesh(cylinder[detail], b.cylinders);
  draw_mesh(sphere[detail], b.spheres);
}

// Only the front-most surface of the batch, blended once: a depth-only pass, then
// a colour pass that passes where the depth equals the stored one. Opaque things
// drawn before stay in front where they are nearer.
void Renderer::Impl::draw_translucent(const Batch& b) {
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

void Renderer::Impl::draw_texts(int width, int height) {
  if (texts.empty()) return;
  gl.Viewport(0, 0, width, height);
  gl.Disable(GL_DEPTH_TEST);
  gl.Enable(GL_BLEND);
  gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.UseProgram(text_program);
  gl.Uniform1i(text_atlas, 0);
  gl.Uniform2f(text_viewport, static_cast<float>(width), static_cast<float>(height));
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
    gl.Uniform4f(text_colour, t.rgba[0], t.rgba[1], t.rgba[2], t.rgba[3]);
    gl.BindTexture(GL_TEXTURE_2D, a.texture);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(), GL_STREAM_DRAW);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v.size() / 4));
  }
  gl.Disable(GL_BLEND);
  gl.Enable(GL_DEPTH_TEST);
  texts.clear();
}

// The width of `text` at a pixel height, in the font drawn.
TextWidth Renderer::Impl::text_width(const std::string& text) {
  return [this, &text](int pixel_height) { return atlas(pixel_height).atlas.text_width(text); };
}

void Renderer::Impl::read_panel(int width, int height, Image& image, const Rect& rect) {
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

}  // namespace rotinterp::render
