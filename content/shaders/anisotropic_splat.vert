#version 450 core
// Anisotropic Gaussian particles (engine/particles/anisotropic_gaussian.h), one instance each,
// back to front; the four corners of a triangle strip come from gl_VertexID.
// Vertex pulling: instance k is the particle draw_order[k], whose record is five vec4s (packed by
// systems/billboard_render/anisotropic_splat_renderer.cpp): centre and peak extinction; the unit
// rotation quaternion (x, y, z, w); the three scales; linear rgb; emitted radiance L_e (rgb).
//
// The quad is the screen rectangle of the particle's ellipsoid m <= 3 in closed form
// (Sigg, Weyrich, Botsch, Gross 2006: the bounding box of a projected quadric), written out in
// engine/math/projected_ellipsoid.h, which this follows step for step: with T = P V M,
// M = [R diag(3 s) | c], r_i the rows of T and <a, b> = a^T diag(1, 1, 1, -1) b,
//   x_ndc = (<r1, r4> -+ sqrt(<r1, r4>^2 - <r1, r1> <r4, r4>)) / <r4, r4>   (r2 for y),
// widened by one pixel against float rounding. A particle that meets the near plane, lies between
// it and the eye or holds the eye covers the whole viewport; one wholly behind the eye, nothing.
// Depth is the centre's (the near plane's when the centre is not beyond it): the splat is depth
// tested against opaque geometry there, as the isotropic billboards are.
// LIT: binding 2 holds each particle's others' depth toward the sun and its gradient
// (components/particle_light.h), in the records' order.
#ifndef LIT
#define LIT 0
#endif
layout(std430, binding = 0) readonly buffer ParticleRecords { vec4 records[]; };
layout(std430, binding = 1) readonly buffer DrawOrder { uint draw_order[]; };
#if LIT
layout(std430, binding = 2) readonly buffer OthersDepth { vec4 others_depth[]; };
#include "lights.glsl"  // the key light
flat out vec4 v_others_depth;
flat out vec3 v_eye_offset;
flat out vec3 v_sun_whitened;
flat out vec3 v_key_toward;    // the key light (lights.glsl) and the ambient light for the
flat out vec3 v_key_radiance;  // fragments: uniform reads in each fragment cost more
flat out vec3 v_ambient;
#endif

uniform mat4 u_view_projection;
uniform mat4 u_inverse_view_projection;
uniform vec3 u_eye;
uniform vec2 u_pixel_ndc;  // one pixel in NDC units: 2 / viewport size

// The pixel's ray from the eye, in world space and whitened: d = P(ndc) - eye w(ndc) with
// (P, w) = inverse(P V) (ndc, 1, 1), a direction (unnormalised) towards the pixel's point on the
// far plane; both d and M d are linear in the window position, so they are interpolated
// exactly (noperspective: every corner has clip w = 1).
noperspective out vec3 v_ray;
noperspective out vec3 v_ray_whitened;
// M = S^-1 R^T (the whitening of engine/math/anisotropic_optical_depth.h) and u0 = M (eye - c).
flat out vec3 v_eye_whitened;
flat out vec4 v_color_extinction;
flat out vec3 v_emission;

const float kExtent = 3.0;  // engine/particles/anisotropic_gaussian.h: kAnisotropicExtent

float dot_d(vec4 a, vec4 b) { return dot(a.xyz, b.xyz) - a.w * b.w; }

vec4 row(mat4 m, int i) { return vec4(m[0][i], m[1][i], m[2][i], m[3][i]); }

// The plane p misses the unit sphere with the centre on its positive side (a relative margin
// makes near-tangent planes count as cutting, the safe side).
bool wholly_positive(vec4 p) { return p.w > 0.0 && length(p.xyz) < p.w * (1.0 - 1e-6); }

vec2 edge_pair(vec4 r, vec4 r4) {
  float a = dot_d(r4, r4), b = dot_d(r, r4), c = dot_d(r, r);
  float root = sqrt(max(b * b - a * c, 0.0));
  float l0 = (b - root) / a, l1 = (b + root) / a;
  return vec2(min(l0, l1), max(l0, l1));
}

void main() {
  uint particle = draw_order[gl_InstanceID];
  vec4 centre_extinction = records[5u * particle];
  vec4 q = records[5u * particle + 1u];
  vec3 scale = records[5u * particle + 2u].xyz;
  vec3 color = records[5u * particle + 3u].rgb;
  v_emission = records[5u * particle + 4u].rgb;
  vec3 centre = centre_extinction.xyz;
  // The local axes in world space: the columns of the rotation matrix of the unit quaternion
  // (w, x, y, z) = (q.w, q.x, q.y, q.z).
  vec3 axis0 = vec3(1.0 - 2.0 * (q.y * q.y + q.z * q.z), 2.0 * (q.x * q.y + q.w * q.z), 2.0 * (q.x * q.z - q.w * q.y));
  vec3 axis1 = vec3(2.0 * (q.x * q.y - q.w * q.z), 1.0 - 2.0 * (q.x * q.x + q.z * q.z), 2.0 * (q.y * q.z + q.w * q.x));
  vec3 axis2 = vec3(2.0 * (q.x * q.z + q.w * q.y), 2.0 * (q.y * q.z - q.w * q.x), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
  mat3 whitening = transpose(mat3(axis0 / scale.x, axis1 / scale.y, axis2 / scale.z));
  v_eye_whitened = whitening * (u_eye - centre);
  v_color_extinction = vec4(color, centre_extinction.w);
#if LIT
  v_others_depth = others_depth[particle];
  v_eye_offset = u_eye - centre;
  v_sun_whitened = whitening * key_toward();
  v_key_toward = key_toward();
  v_key_radiance = key_radiance();
  v_ambient = ambient_light();
#endif

  mat4 t = u_view_projection * mat4(vec4(axis0 * (kExtent * scale.x), 0.0), vec4(axis1 * (kExtent * scale.y), 0.0),
                                    vec4(axis2 * (kExtent * scale.z), 0.0), vec4(centre, 1.0));
  vec4 r1 = row(t, 0), r2 = row(t, 1), r3 = row(t, 2), r4 = row(t, 3);
  vec4 near_plane = r3 + r4;
  float depth = near_plane.w > 0.0 ? r3.w / r4.w : -1.0;
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1));
  vec2 ndc = corner * 2.0 - 1.0;
  if (wholly_positive(near_plane)) {
    vec2 x = edge_pair(r1, r4), y = edge_pair(r2, r4);
    vec2 lo = vec2(x[0], y[0]) - u_pixel_ndc, hi = vec2(x[1], y[1]) + u_pixel_ndc;
    ndc = mix(lo, hi, corner);
  } else if (wholly_positive(-r4)) {
    ndc = vec2(2.0);  // hidden: a point outside the clip volume
    depth = 2.0;
  }
  gl_Position = vec4(ndc, depth, 1.0);
  vec4 far_point = u_inverse_view_projection * vec4(ndc, 1.0, 1.0);
  v_ray = far_point.xyz - u_eye * far_point.w;
  v_ray_whitened = whitening * v_ray;
}
