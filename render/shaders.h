// The renderer's GLSL programs: instanced lit meshes, coloured lines, and text from
// a glyph atlas.
#pragma once

namespace rotinterp::render {

// Instanced meshes (bone cylinders, joint spheres) with simple lighting: a
// hemisphere ambient, one directional light and a little Blinn–Phong specular.
inline constexpr const char* kMeshVertex = R"(#version 330 core
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

inline constexpr const char* kMeshFragment = R"(#version 330 core
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

inline constexpr const char* kLineVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_projection;
out vec4 v_color;
void main() {
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

inline constexpr const char* kLineFragment = R"(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)";

// Text: quads in pixels (y downwards), coverage from the glyph atlas.
inline constexpr const char* kTextVertex = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
uniform vec2 u_viewport;
out vec2 v_uv;
void main() {
  v_uv = a_uv;
  gl_Position = vec4(a_position.x / u_viewport.x * 2.0 - 1.0, 1.0 - a_position.y / u_viewport.y * 2.0, 0.0, 1.0);
}
)";

inline constexpr const char* kTextFragment = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_atlas;
uniform vec4 u_color;
out vec4 o_color;
void main() { o_color = vec4(u_color.rgb, u_color.a * texture(u_atlas, v_uv).r); }
)";

}  // namespace rotinterp::render
