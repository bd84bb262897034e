#version 450 core
// Opaque procedural meshes: position and normal per vertex, one placement per draw.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view_projection;
uniform vec3 u_offset;
uniform float u_scale;

out vec3 v_normal;
out vec3 v_world;

void main() {
  v_normal = a_normal;
  v_world = a_position * u_scale + u_offset;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
