#include "rotinterp/render/renderer.h"

#include "font.h"
#include "gl_api.h"
#include "rotinterp/render/layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
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
out vec4 o_color;
void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 v = normalize(u_eye - v_world);
  float diffuse = max(dot(n, u_light), 0.0);
  float hemisphere = 0.5 + 0.5 * n.y;
  vec3 h = normalize(u_light + v);
  float specular = pow(max(dot(n, h), 0.0), 40.0) * 0.25;
  vec3 rgb = v_color.rgb * (0.28 + 0.17 * hemisphere + 0.62 * diffuse) + vec3(specular);
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
constexpr float kInsetBackground[3] = {0.120f, 0.128f, 0.145f};
constexpr float kTitleText[4] = {0.93f, 0.93f, 0.93f, 1.0f};
constexpr float kGridLine[4] = {0.30f, 0.32f, 0.35f, 1.0f};
constexpr float kSphereWire[4] = {0.30f, 0.32f, 0.36f, 1.0f};
constexpr Color kGhostColor = {0.84f, 0.87f, 0.92f};
constexpr float kGhostAlpha = 0.33f;
constexpr Color kKeyMarker = {0.96f, 0.96f, 0.96f};

// Trail geometry on the unit sphere (sphere radii).
constexpr float kTrailReferenceRadius = 0.034f;
constexpr float kTrailMethodRadius = 0.017f;
constexpr float kTrailKeyRadius = 0.036f;
constexpr float kTrailCurrentRadius = 0.065f;
constexpr std::size_t kMaxTrailSegments = 720;  // longer trails are drawn with a stride
constexpr std::size_t kMaxKeyMarkers = 64;      // more keys than this are not marked (clutter)

// ---- meshes ------------------------------------------------------------------

struct Instance {
  float model[16];  // column-major
  float color[4];
};

struct Mesh {
  GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
  GLsizei index_count = 0;
};

using Vertices = std::vector<float>;  // x y z nx ny nz
using Indices = std::vector<unsigned>;

// Radius 1, from z = 0 to z = 1, open (joint spheres close it).
void cylinder_mesh(int sides, Vertices& v, Indices& idx) {
  for (int i = 0; i <= sides; ++i) {
    const double a = kTwoPi * i / sides;
    const float c = static_cast<float>(std::cos(a)), s = static_cast<float>(std::sin(a));
    for (float z : {0.0f, 1.0f}) v.insert(v.end(), {c, s, z, c, s, 0.0f});
  }
  for (unsigned i = 0; i < static_cast<unsigned>(sides); ++i) {
    const unsigned a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    idx.insert(idx.end(), {a, c, b, b, c, d});
  }
}

// Unit sphere, latitude/longitude.
void sphere_mesh(int slices, int stacks, Vertices& v, Indices& idx) {
  for (int j = 0; j <= stacks; ++j) {
    const double phi = kPi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double theta = kTwoPi * i / slices;
      const float x = static_cast<float>(std::sin(phi) * std::cos(theta));
      const float y = static_cast<float>(std::cos(phi));
      const float z = static_cast<float>(std::sin(phi) * std::sin(theta));
      v.insert(v.end(), {x, y, z, x, y, z});
    }
  }
  const unsigned row = static_cast<unsigned>(slices + 1);
  for (unsigned j = 0; j < static_cast<unsigned>(stacks); ++j)
    for (unsigned i = 0; i < static_cast<unsigned>(slices); ++i) {
      const unsigned a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      idx.insert(idx.end(), {a, b, c, b, d, c});
    }
}

Eigen::Matrix4f to_float(const Eigen::Matrix4d& m) { return m.cast<float>(); }

Instance make_instance(const Eigen::Matrix4d& model, const Color& color, float alpha) {
  Instance in;
  const Eigen::Matrix4f f = model.cast<float>();
  std::memcpy(in.model, f.data(), sizeof in.model);  // Eigen is column-major, like GL
  in.color[0] = color[0];
  in.color[1] = color[1];
  in.color[2] = color[2];
  in.color[3] = alpha;
  return in;
}

// Batches of instances for one look (colour, alpha).
struct Batch {
  std::vector<Instance> cylinders;
  std::vector<Instance> spheres;
  void clear() {
    cylinders.clear();
    spheres.clear();
  }
  void sphere(const Vec3& p, double radius, const Color& color, float alpha) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 3>(0, 0) = Mat3::Identity() * radius;
    m.block<3, 1>(0, 3) = p;
    spheres.push_back(make_instance(m, color, alpha));
  }
  // A capsule's body from a to b; skipped when shorter than `min_length`.
  void cylinder(const Vec3& a, const Vec3& b, double radius, double min_length, const Color& color, float alpha) {
    const Vec3 d = b - a;
    const double length = d.norm();
    if (!(length > min_length)) return;
    const Mat3 r = Quat::FromTwoVectors(Vec3::UnitZ(), d / length).toRotationMatrix();
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 3>(0, 0) = r * Eigen::Vector3d(radius, radius, length).asDiagonal();
    m.block<3, 1>(0, 3) = a;
    cylinders.push_back(make_instance(m, color, alpha));
  }
};

bool pose_usable(const WorldPose& pose, const Skeleton& skeleton) {
  return pose.position.size() == skeleton.joints.size() && !pose.position.empty();
}

// Capsule bones joint → parent and End Site → joint, and a sphere at every joint.
void add_pose(const Skeleton& skeleton, const WorldPose& pose, double radius, const Color& color, float alpha,
              Batch& batch) {
  if (!pose_usable(pose, skeleton)) return;
  const double min_length = radius * 1e-3;
  for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
    const int p = skeleton.joints[j].parent;
    if (p >= 0) batch.cylinder(pose.position[static_cast<std::size_t>(p)], pose.position[j], radius, min_length, color, alpha);
    batch.sphere(pose.position[j], radius, color, alpha);
  }
  if (pose.end_site_position.size() != skeleton.end_sites.size()) return;
  for (std::size_t e = 0; e < skeleton.end_sites.size(); ++e) {
    const Vec3& a = pose.position[static_cast<std::size_t>(skeleton.end_sites[e].parent)];
    const Vec3& b = pose.end_site_position[e];
    batch.cylinder(a, b, radius, min_length, color, alpha);
    batch.sphere(b, radius, color, alpha);
  }
}

Vec3 unit_or_zero(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 && std::isfinite(n) ? Vec3(v / n) : Vec3::Zero();
}

// A tube through `points` (every `stride`-th, and the last).
void add_curve(const std::vector<Vec3>& points, std::size_t stride, double radius, const Color& color, float alpha,
               Batch& batch) {
  if (points.empty()) return;
  std::size_t previous = 0;
  batch.sphere(unit_or_zero(points[0]), radius, color, alpha);
  for (std::size_t i = stride; ; i += stride) {
    const std::size_t k = std::min(i, points.size() - 1);
    if (k == previous) break;
    const Vec3 a = unit_or_zero(points[previous]), b = unit_or_zero(points[k]);
    batch.cylinder(a, b, radius, 1e-6, color, alpha);
    batch.sphere(b, radius, color, alpha);
    previous = k;
  }
}

void push_line(std::vector<float>& lines, const Vec3& a, const Vec3& b, const float rgba[4]) {
  for (const Vec3* p : {&a, &b})
    lines.insert(lines.end(), {static_cast<float>(p->x()), static_cast<float>(p->y()), static_cast<float>(p->z()),
                               rgba[0], rgba[1], rgba[2], rgba[3]});
}

struct TextItem {
  std::string text;
  float x;         // left, pixels
  float top;       // top of the line box, pixels from the panel's top
  int pixel_height;
};

}  // namespace

double scene_bone_radius(const Skeleton& skeleton, const Bounds& bounds) {
  std::vector<double> lengths;
  for (const Joint& j : skeleton.joints)
    if (j.parent >= 0 && j.offset.norm() > 0.0) lengths.push_back(j.offset.norm());
  for (const EndSite& e : skeleton.end_sites)
    if (e.offset.norm() > 0.0) lengths.push_back(e.offset.norm());
  const double diagonal = bounds.empty() ? 1.0 : std::max(bounds.size().norm(), 1e-9);
  if (lengths.empty()) return 0.01 * diagonal;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  const double median = lengths[lengths.size() / 2];
  return std::clamp(0.1 * median, 0.004 * diagonal, 0.02 * diagonal);
}

struct Renderer::Impl {
  std::unique_ptr<GLContext> context;
  GLApi gl;
  Scene scene;
  int samples = 1;

  GLuint mesh_program = 0, line_program = 0, text_program = 0;
  GLint mesh_view_projection = -1, mesh_light = -1, mesh_eye = -1;
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

  std::vector<float> grid_lines;    // world space
  std::vector<float> sphere_lines;  // unit sphere wireframe
  Batch batch;
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

  void make_mesh(Mesh& mesh, const Vertices& v, const Indices& idx) {
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
    if (!mesh) return make_error(mesh.error());
    mesh_program = *mesh;
    auto line = compile(kLineVertex, kLineFragment, "line");
    if (!line) return make_error(line.error());
    line_program = *line;
    auto text = compile(kTextVertex, kTextFragment, "text");
    if (!text) return make_error(text.error());
    text_program = *text;
    mesh_view_projection = gl.GetUniformLocation(mesh_program, "u_view_projection");
    mesh_light = gl.GetUniformLocation(mesh_program, "u_light");
    mesh_eye = gl.GetUniformLocation(mesh_program, "u_eye");
    line_view_projection = gl.GetUniformLocation(line_program, "u_view_projection");
    text_viewport = gl.GetUniformLocation(text_program, "u_viewport");
    text_color = gl.GetUniformLocation(text_program, "u_color");
    text_atlas = gl.GetUniformLocation(text_program, "u_atlas");

    Vertices v;
    Indices idx;
    for (int level = 0; level < 2; ++level) {
      v.clear();
      idx.clear();
      cylinder_mesh(level ? 24 : 10, v, idx);
      make_mesh(cylinder[level], v, idx);
      v.clear();
      idx.clear();
      sphere_mesh(level ? 24 : 10, level ? 14 : 6, v, idx);
      make_mesh(sphere[level], v, idx);
    }
    make_dynamic(line_vao, line_vbo, 3, 4);
    make_dynamic(text_vao, text_vbo, 2, 2);

    auto f = FontFile::load(ROTINTERP_FONT_PATH);
    if (!f) return make_error(f.error());
    font = *f;

    build_static_lines();
    if (GLenum e = gl.GetError(); e != GL_NO_ERROR) return gl_error("setup", e);
    return Ok{};
  }

  Error gl_error(const char* where, GLenum code) const {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", code);
    return make_error(std::string(backend_name(context->backend())) + ": OpenGL error " + hex + " during " + where);
  }

  void build_static_lines() {
    const GroundGrid g = ground_grid(scene.bounds);
    const auto nx = static_cast<long>(std::llround((g.x1 - g.x0) / g.step));
    const auto nz = static_cast<long>(std::llround((g.z1 - g.z0) / g.step));
    for (long i = 0; i <= nx; ++i) {
      const double x = g.x0 + static_cast<double>(i) * g.step;
      push_line(grid_lines, Vec3(x, g.y, g.z0), Vec3(x, g.y, g.z1), kGridLine);
    }
    for (long i = 0; i <= nz; ++i) {
      const double z = g.z0 + static_cast<double>(i) * g.step;
      push_line(grid_lines, Vec3(g.x0, g.y, z), Vec3(g.x1, g.y, z), kGridLine);
    }
    // Unit sphere: parallels every 30°, meridians every 30°, 48 segments each.
    constexpr int kSegments = 48;
    auto point = [](double lat, double lon) {
      return Vec3(std::cos(lat) * std::sin(lon), std::sin(lat), std::cos(lat) * std::cos(lon));
    };
    for (int p = -2; p <= 2; ++p)
      for (int s = 0; s < kSegments; ++s)
        push_line(sphere_lines, point(p * kPi / 6, kTwoPi * s / kSegments), point(p * kPi / 6, kTwoPi * (s + 1) / kSegments),
                  kSphereWire);
    for (int m = 0; m < 6; ++m)
      for (int s = 0; s < kSegments; ++s)
        push_line(sphere_lines, point(-kPi / 2 + kPi * s / kSegments, m * kPi / 6),
                  point(-kPi / 2 + kPi * (s + 1) / kSegments, m * kPi / 6), kSphereWire);
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
    const double pixels = radius / ((camera.eye - camera.target).norm() * std::tan(0.5 * camera.fov_y)) *
                          0.5 * viewport_height;
    detail = pixels >= 6.0 ? 1 : 0;
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

  // A text line fitting `max_width`: the pixel height shrinks (not below 8 px) until
  // it fits; past that the text is clipped by the panel.
  int fitting_height(const std::string& text, int pixel_height, float max_width) {
    while (pixel_height > 8 && atlas(pixel_height).atlas.text_width(text) > max_width) --pixel_height;
    return pixel_height;
  }

  // The trail inset (GL coordinates, y from the bottom); `height` is the panel's.
  void draw_trail(const Panel& panel, const Trail& trail, const Rect& inset, int height) {
    const int side = inset.width, x = inset.x, y = inset.y;
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(x, y, side, side);
    gl.ClearColor(kInsetBackground[0], kInsetBackground[1], kInsetBackground[2], 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Viewport(x, y, side, side);

    // Look at the sphere from the trail's mean direction, so the curve faces the
    // viewer; the scene's view direction where the mean is near zero.
    Vec3 mean = Vec3::Zero();
    for (const Vec3& d : trail.reference) mean += unit_or_zero(d);
    mean /= static_cast<double>(trail.reference.size());
    Vec3 toward;
    if (mean.norm() > 0.2) {
      toward = mean.normalized();
    } else {
      const double az = scene.view.azimuth_deg * kPi / 180.0;
      const double el = std::max(scene.view.elevation_deg, 20.0) * kPi / 180.0;
      toward = Vec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
    }
    Camera camera;
    camera.eye = 3.9 * toward;
    camera.target = Vec3::Zero();
    camera.up = std::abs(toward.y()) < 0.95 ? Vec3::UnitY() : Vec3::UnitZ();
    // Zoom on the curves: the field of view holds the farthest sample from the view
    // axis with a margin; at most the whole sphere (half-angle 18°), at least 1.5°.
    double spread = 0.0;
    for (const std::vector<Vec3>* curve : {&trail.reference, &trail.method})
      for (const Vec3& d : *curve) {
        const Vec3 u = unit_or_zero(d);
        spread = std::max(spread, (u - u.dot(toward) * toward).norm() / (camera.eye.norm() - std::max(u.dot(toward), 0.0)));
      }
    const double max_half = 18.0 * kPi / 180.0;
    const double half = std::clamp(std::atan(1.25 * spread + 0.02), 1.5 * kPi / 180.0, max_half);
    const double zoom = std::tan(half) / std::tan(max_half);  // tubes and markers shrink with the view
    camera.fov_y = 2.0 * half;
    camera.aspect = 1.0;
    camera.near_plane = 2.0;
    camera.far_plane = 6.0;
    draw_lines(sphere_lines, to_float(camera.projection() * camera.view()));

    const std::size_t n = trail.reference.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + kMaxTrailSegments - 1) / kMaxTrailSegments);
    use_mesh_program(camera, zoom * kTrailReferenceRadius, side);
    batch.clear();
    add_curve(trail.method, stride, zoom * kTrailMethodRadius, panel.color, 1.0f, batch);
    if (trail.keys.size() <= kMaxKeyMarkers)
      for (std::size_t k : trail.keys)
        if (k < trail.method.size()) batch.sphere(unit_or_zero(trail.method[k]), zoom * kTrailKeyRadius, kKeyMarker, 1.0f);
    if (trail.current < trail.method.size())
      batch.sphere(unit_or_zero(trail.method[trail.current]), zoom * kTrailCurrentRadius, panel.color, 1.0f);
    draw_opaque(batch);
    batch.clear();
    add_curve(trail.reference, stride, zoom * kTrailReferenceRadius, kGhostColor, kGhostAlpha, batch);
    if (trail.current < n)
      batch.sphere(unit_or_zero(trail.reference[trail.current]), zoom * kTrailCurrentRadius * 1.25, kGhostColor, kGhostAlpha);
    draw_translucent(batch);
    gl.Disable(GL_SCISSOR_TEST);

    if (!trail.label.empty()) {
      const float pad = static_cast<float>(std::max(3, side / 40));
      const int px = fitting_height(trail.label, std::clamp(side / 11, 9, 22), static_cast<float>(side) - 2 * pad);
      // Pixel rows from the panel's top: the inset's top edge is at height − (y + side).
      texts.push_back(TextItem{trail.label, static_cast<float>(x) + pad, static_cast<float>(height - (y + side)) + pad, px});
    }
  }

  Status draw_panel(const Panel& panel, int width, int height) {
    const int title_height = std::clamp(static_cast<int>(std::lround(0.075 * height)), 14, 40);
    const int scene_height = height - title_height;
    gl.BindFramebuffer(GL_FRAMEBUFFER, msaa_fbo);
    gl.Viewport(0, 0, width, height);
    gl.Disable(GL_SCISSOR_TEST);
    gl.ClearColor(kBackground[0], kBackground[1], kBackground[2], 1.0f);
    gl.ClearDepth(1.0);
    gl.DepthMask(GL_TRUE);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(0, scene_height, width, title_height);
    gl.ClearColor(kTitleStrip[0], kTitleStrip[1], kTitleStrip[2], 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.Disable(GL_SCISSOR_TEST);

    // With a trail the figure and the inset share the scene area without
    // overlapping: the inset below the figure in tall panels, beside it in wide ones.
    Rect view{0, 0, width, scene_height};
    Rect inset;
    if (panel.trail && !panel.trail->reference.empty()) {
      const int margin = std::max(4, std::min(width, scene_height) / 60);
      if (width * 5 <= scene_height * 6) {
        const int side = std::min(width - 2 * margin, static_cast<int>(std::lround(0.34 * scene_height)));
        inset = Rect{width - side - margin, margin, side, side};
        view = Rect{0, side + margin, width, scene_height - side - margin};
      } else {
        const int side = std::min(scene_height - 2 * margin, static_cast<int>(std::lround(0.34 * width)));
        inset = Rect{width - side - margin, scene_height - side - margin, side, side};
        view = Rect{0, 0, width - side - margin, scene_height};
      }
    }
    gl.Viewport(view.x, view.y, view.width, view.height);
    gl.Enable(GL_DEPTH_TEST);
    gl.Enable(GL_MULTISAMPLE);
    const Camera camera = frame_bounds(scene.bounds, static_cast<double>(view.width) / view.height, scene.view);
    draw_lines(grid_lines, to_float(camera.projection() * camera.view()));
    use_mesh_program(camera, scene.bone_radius, view.height);
    batch.clear();
    add_pose(scene.skeleton, panel.pose, scene.bone_radius, panel.color, 1.0f, batch);
    draw_opaque(batch);
    batch.clear();
    add_pose(scene.skeleton, panel.ghost, scene.bone_radius * 1.02, kGhostColor, kGhostAlpha, batch);
    draw_translucent(batch);
    if (inset.width >= 32) draw_trail(panel, *panel.trail, inset, height);

    const float pad = static_cast<float>(std::max(4, title_height / 3));
    const int px = fitting_height(panel.title, static_cast<int>(std::lround(0.62 * title_height)),
                                  static_cast<float>(width) - 2 * pad);
    const float line = static_cast<float>(px) * 1.15f;
    texts.push_back(TextItem{panel.title, pad, std::round((static_cast<float>(title_height) - line) * 0.5f), px});
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
  if (Status s = scene.skeleton.validate(); !s) return make_error("render: " + s.error());
  auto impl = std::make_unique<Impl>();
  impl->context = std::move(context);
  if (!(scene.bone_radius > 0.0) || !std::isfinite(scene.bone_radius))
    scene.bone_radius = scene_bone_radius(scene.skeleton, scene.bounds);
  impl->scene = std::move(scene);
  if (Status s = impl->context->make_current(); !s) return make_error(s.error());
  if (Status s = impl->setup(); !s) return make_error(s.error());
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
  if (Status s = check_image_size(width, height, count, columns); !s) return make_error("render: " + s.error());
  if (columns <= 0) columns = automatic_columns(count, width, height);
  const std::vector<Rect> rects = grid_layout(count, columns, width, height);
  const Rect& first = rects.front();
  Impl& m = *impl_;
  if (Status s = m.context->make_current(); !s) return make_error(s.error());
  if (Status s = m.ensure_framebuffers(first.width, first.height); !s) return make_error(s.error());
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = static_cast<std::uint8_t>(std::lround(kBackground[0] * 255));
    image.rgb[i + 1] = static_cast<std::uint8_t>(std::lround(kBackground[1] * 255));
    image.rgb[i + 2] = static_cast<std::uint8_t>(std::lround(kBackground[2] * 255));
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    if (Status s = m.draw_panel(panels[i], first.width, first.height); !s) return make_error(s.error());
    m.read_panel(first.width, first.height, image, rects[i]);
  }
  if (GLenum e = m.gl.GetError(); e != GL_NO_ERROR) return m.gl_error("reading pixels", e);
  return image;
}

}  // namespace rotinterp::render
