#version 450 core
// Instanced particle billboards facing the viewplane (Johnson & McAllister 2005, 2.2.1): every
// billboard of an eye shares the camera's right and up axes. One instance per particle; the four
// corners come from gl_VertexID (triangle strip).
layout(location = 0) in vec4 a_center_radius;  // world xyz, radius
layout(location = 1) in vec4 a_color_density;  // linear rgb, density rho

uniform mat4 u_view_projection;
uniform vec3 u_right;
uniform vec3 u_up;
// Maps the billboard's edge-to-edge coordinate s in [0, 1] to the texture coordinate of the
// footprint table's first and last nodes (engine/math/footprint.h, footprint_texcoord).
uniform vec2 u_texcoord_bias_scale;

out vec2 v_texcoord;
flat out vec4 v_premultiplied;  // (rgb * rho, rho): one value per billboard, not interpolated

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  vec3 world = a_center_radius.xyz +
               (u_right * corner.x + u_up * corner.y) * a_center_radius.w;
  v_texcoord = u_texcoord_bias_scale.x + (corner * 0.5 + 0.5) * u_texcoord_bias_scale.y;
  v_premultiplied = vec4(a_color_density.rgb * a_color_density.a, a_color_density.a);
  gl_Position = u_view_projection * vec4(world, 1.0);
}
