#version 450 core
// Spherical billboards (Umenhoffer, Szirmay-Kalos & Szijarto 2006, section 2): each particle is
// a sphere of radius r; its primitive only has to cover the sphere's image, and the fragment
// shader finds the real path length of the pixel's ray inside the sphere.
//
// Two primitives, chosen per particle by the caller (systems/billboard_render/
// sphere_billboard_programs.cpp) and drawn in runs that keep the back-to-front order:
// - a point sprite (u_sprite 1, one vertex) over the exact screen rectangle of the sphere's
//   image, for spheres wholly in front of the near plane whose sprite fits the implementation's
//   largest point size: its centre, side and depth come with the instance (a_sprite), made on
//   the CPU, which chooses the primitive (sphere_billboard_sprite; engine/math/
//   projected_sphere.h derives the rectangle). One square per particle: llvmpipe shades the 4x4
//   blocks a quad's diagonal crosses once for each of its triangles.
// - a quad (u_sprite 0, a 4-vertex strip) otherwise. Unlike the paper's quad (perpendicular to
//   z at the sphere's far point, half size r), ours is perpendicular to the eye-to-centre axis at
//   distance D + r with half size r (D + r) / sqrt(D^2 - r^2): it contains the tangent cone, so
//   the whole silhouette is covered under perspective, and it lies behind every point of the
//   sphere, so the near plane never cuts it before the sphere. An eye inside (or very near) the
//   sphere gets a quad over the whole target.
// PLANAR 1 (a define: see sphere_billboard.frag) draws the classic planar billboard instead
// (through the centre, facing the viewplane, depth tested) for comparison: a square of half side
// r at the centre's depth, as a sprite of its screen size (a_sprite likewise) or as a quad.
#ifndef PLANAR
#define PLANAR 0
#endif
#ifndef LIT
#define LIT 0
#endif
layout(location = 0) in vec4 a_center_radius;  // world xyz, radius
layout(location = 1) in vec4 a_color_tau;      // linear rgb, extinction tau (1 / length)
layout(location = 2) in vec4 a_medium;  // temperature K, opacity, medium, detail key (explosions)
layout(location = 3) in vec4 a_sprite;  // u_sprite 1: centre (target pixels), side (pixels), ndc depth
#if LIT
// LIT (sphere_billboard.frag): the other particles' optical depth toward the sun at the centre,
// and its gradient (world space; turned into view space for the fragments).
layout(location = 4) in vec4 a_light;
flat out vec4 v_light;
// The fire's clustered lights (lights.glsl; here in view space), scattered at the centre toward
// the eye (fire_light.glsl): constant over the particle.
uniform float u_g;
flat out vec3 v_fire;
#include "cornette_shanks.glsl"
#include "fire_light.glsl"
#endif

uniform mat4 u_view;
uniform mat4 u_projection;
#ifndef SHADING
#define SHADING 0
#endif
#if SHADING == 1 || LIT
#include "lights.glsl"
#endif
#if SHADING == 1
flat out vec3 v_light_view;  // the way the key light travels, view space, unit (dust and smoke)
#endif
uniform int u_sprite;          // 1: this draw's particles are point sprites; 0: quads
// The target: u_viewport pixels from u_target_origin in the framebuffer (a cell of the media
// atlas, or all of it). The GL viewport reaches u_guard pixels past the framebuffer on every side,
// so that a sprite whose centre lies off the target but which overlaps it is not clipped with
// its centre; the scissor keeps the target's pixels.
uniform vec2 u_viewport;
uniform vec2 u_target_origin;
uniform vec4 u_gl_viewport;    // the GL viewport: x, y, width, height

// Clip position q of the target's view to the GL viewport: window = origin + (ndc + 1) / 2 size
// in the target, then to the GL viewport's ndc, written for clip coordinates (times w).
vec4 into_viewport(vec4 q) {
  vec2 scale = u_viewport / u_gl_viewport.zw;
  vec2 shift = 2.0 * (u_target_origin - u_gl_viewport.xy) / u_gl_viewport.zw - 1.0;
  q.xy = (q.xy + q.w) * scale + q.w * shift;
  return q;
}

// Target pixels to the GL viewport's ndc.
vec2 pixels_to_ndc(vec2 pixels) {
  return (pixels + u_target_origin - u_gl_viewport.xy) / u_gl_viewport.zw * 2.0 - 1.0;
}

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
#if SHADING == 1
  v_light_view = key_travel_in(u_view);
#endif
#if LIT
  v_light = vec4(a_light.x, mat3(u_view) * a_light.yzw);
  v_fire = vec3(0.0);
  for (int j = 0; j < fire_light_count(); ++j) {
    // In view space as the CPU's maths (glm) rotates and moves it: sums in that order, unfused.
    vec3 q = lights_fire_position[j].xyz;
    precise vec4 v = u_view[0] * q.x + u_view[1] * q.y;
    precise vec4 w = u_view[2] * q.z + u_view[3];
    v = v + w;
    vec4 light = vec4(v.xyz, lights_fire_position[j].w);
    v_fire += fire_light_inscattered(light, lights_fire_intensity[j].rgb, p, -normalize(p), u_g);
  }
#endif
  if (u_sprite == 1) {
    gl_PointSize = a_sprite.z;
    gl_Position = vec4(pixels_to_ndc(a_sprite.xy), a_sprite.w, 1.0);
    return;
  }
#if PLANAR
  gl_Position = into_viewport(u_projection * vec4(p + vec3(corner * r, 0.0), 1.0));
#else
  float d = length(p);
  if (d < 2.0 * r) {
    gl_Position = into_viewport(vec4(corner, 0.0, 1.0));
    return;
  }
  vec3 axis = p / d;
  vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(axis, helper));
  vec3 up = cross(right, axis);
  float distance = d + r;
  float half_size = r * distance / sqrt(d * d - r * r);
  gl_Position = into_viewport(u_projection * vec4(axis * distance + (right * corner.x + up * corner.y) * half_size, 1.0));
#endif
}
