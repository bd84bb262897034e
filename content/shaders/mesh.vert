#version 450 core
// Opaque meshes: position and normal per vertex in model space, one placement per draw
// (engine/mesh/mesh_placement.h: p_world = position + scale R p_model; normals turn by R).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view_projection;
uniform mat4 u_model;     // scale R, then position
uniform mat3 u_rotation;  // R: the normals' transform (uniform scale keeps them perpendicular)

out vec3 v_normal;
out vec3 v_world;

void main() {
  v_normal = u_rotation * a_normal;
  v_world = (u_model * vec4(a_position, 1.0)).xyz;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
