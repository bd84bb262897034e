#version 450 core
// Spherical billboards (Umenhoffer, Szirmay-Kalos & Szijarto 2006, section 2): each particle is
// a sphere of radius r; its quad only has to cover the sphere's image, and the fragment shader
// finds the real path length of the pixel's ray inside the sphere.
// Unlike the paper's quad (perpendicular to z at the sphere's far point, half size r), ours is
// perpendicular to the eye-to-centre axis at distance D + r with half size r (D + r) / sqrt(D^2 -
// r^2): it contains the tangent cone, so the whole silhouette is covered under perspective, and
// it lies behind every point of the sphere, so the near plane never cuts it before the sphere.
// An eye inside (or very near) the sphere gets a full-viewport quad.
// PLANAR 1 (a define: see sphere_billboard.frag) draws the classic planar billboard instead
// (through the centre, facing the viewplane, depth tested) for comparison.
#ifndef PLANAR
#define PLANAR 0
#endif
// CELLS 1 (explosion media): the target is an atlas of layers side by side; this draw's layer is
// the cell of u_viewport's size from column u_cell_origin. The view maps onto the cell, whose
// sides clip (gl_ClipDistance 0 and 1: GL_CLIP_DISTANCE0/1 enabled), so no billboard spills into
// its neighbour.
#ifndef CELLS
#define CELLS 0
#endif
layout(location = 0) in vec4 a_center_radius;  // world xyz, radius
layout(location = 1) in vec4 a_color_tau;      // linear rgb, extinction tau (1 / length)
layout(location = 2) in vec4 a_medium;  // temperature K, opacity, medium, detail key (explosions)

uniform mat4 u_view;
uniform mat4 u_projection;
#if CELLS
uniform vec2 u_viewport;       // the cell's size in pixels
uniform float u_cell_origin;   // its first column in the atlas
uniform float u_atlas_width;   // the atlas's width in pixels

// Clip position q in the cell's view to the atlas: x_ndc in [-1, 1] onto the cell's columns,
// x_window = origin + (x_ndc + 1) / 2 * cell width, written for clip coordinates (times w).
vec4 into_cell(vec4 q) {
  gl_ClipDistance[0] = q.w + q.x;
  gl_ClipDistance[1] = q.w - q.x;
  q.x = (q.x + q.w) * (u_viewport.x / u_atlas_width) + q.w * (2.0 * u_cell_origin / u_atlas_width - 1.0);
  return q;
}
#else
vec4 into_cell(vec4 q) { return q; }
#endif

flat out vec3 v_center;  // view space
flat out float v_radius;
flat out vec4 v_color_tau;
flat out vec4 v_medium;

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  vec3 p = (u_view * vec4(a_center_radius.xyz, 1.0)).xyz;
  float r = a_center_radius.w;
  v_center = p;
  v_radius = r;
  v_color_tau = a_color_tau;
  v_medium = a_medium;
#if PLANAR
  gl_Position = into_cell(u_projection * vec4(p + vec3(corner * r, 0.0), 1.0));
#else
  float d = length(p);
  if (d < 2.0 * r) {
    gl_Position = into_cell(vec4(corner, 0.0, 1.0));
    return;
  }
  vec3 axis = p / d;
  vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(axis, helper));
  vec3 up = cross(right, axis);
  float distance = d + r;
  float half_size = r * distance / sqrt(d * d - r * r);
  gl_Position = into_cell(u_projection * vec4(axis * distance + (right * corner.x + up * corner.y) * half_size, 1.0));
#endif
}
