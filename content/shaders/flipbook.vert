#version 450 core
// Flipbook fire billboards (Rose 2007, chapter 4): world-space corners computed on the CPU
// (systems/flipbook_fire/flipbook_geometry.h), one layer of the frame array per billboard.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_uv_layer;   // u, v (0 at the top), frame
layout(location = 2) in float a_intensity;
layout(location = 3) in vec3 a_next_blend_scale;  // next frame, fraction of the way, motion scale

uniform mat4 u_view_projection;

out vec3 v_uv_layer;
out float v_intensity;
out vec3 v_next_blend_scale;

void main() {
  v_uv_layer = a_uv_layer;
  v_intensity = a_intensity;
  v_next_blend_scale = a_next_blend_scale;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
