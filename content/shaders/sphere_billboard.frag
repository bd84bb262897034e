#version 450 core
// Opacity of a spherical particle along this pixel's ray (Umenhoffer et al. 2006, eq. 2 and
// section 2.2): alpha = 1 - exp(-tau (1 - d/r) ds), where d is the ray's distance from the
// centre and ds the length of the ray inside the sphere, clipped by the near plane and by the
// opaque scene's depth. Unlike the paper, which takes rays parallel to z inside a particle,
// ds comes from the exact ray-sphere intersection of the perspective ray.
// Output premultiplied; blending (ONE, ONE_MINUS_SRC_ALPHA), back to front.
//
// Variants (gpu::load_program's defines; on llvmpipe a uniform branch still runs both sides):
// PLANAR 1 for the planar billboard (full chord, depth tested), 0 spherical; SHADING 0 the
// particle's colour, 1 dust or smoke, 2 fire.
#ifndef PLANAR
#define PLANAR 0
#endif
#ifndef SHADING
#define SHADING 0
#endif
#ifndef LIT
#define LIT 0
#endif
//
// SHADING 1 and 2 shade explosion media (section 3) by eq. 1,
// L = I (1 - alpha) + alpha a C + alpha (1 - a) L_e, written premultiplied as
// (alpha a C + alpha (1 - a) L_e, alpha):
//   1, dust and smoke: L_e = 0; C = E P(mu) T_light + ambient, P the Cornette-Shanks phase
//      function (cornette_shanks.glsl),
//      T_light the light's transmittance from the sphere's surface to the middle of the ray's
//      segment; opacity perturbed by the detail noise;
//   2, fire: a = 0; L_e from the black-body table engine/math/blackbody.h makes, at the
//      temperature perturbed by the detail noise (the paper's T = T0 + T1 tex3D(...)).
// LIT (docs/lighting.md; dust and smoke) shadows the medium by the others too, in one model for
// every ray: a particle's extinction along a ray at distance d from its centre is tau (1 - d/r)
// (engine/math/sphere_line_integral.h), so T_light = exp(-(others + own)), own that closed form
// along the light's chord from the middle point, and
//   LIT 1: others = the light phase's optical depth of the other particles at the centre plus
//          its gradient times the offset (v_light);
//   LIT 2: others and own summed exactly over every particle of the list (u_casters): the truth
//          the benchmark measures the light phase's methods against, O(particles) a fragment.
// Lit, they also scatter the fire's light (components/fire_lights.h): point sources of intensity
// I at p, irradiance I / max(|x - p|^2, r^2), scattered by the same phase function; LIT 1 from
// the light phase's few clustered lights, at the particle's centre (the vertex shader: one
// evaluation a particle, not one a fragment), LIT 2 from every fire particle, per fragment.
// The detail noise (engine/math/detail_noise.h) is sampled in each particle's own window: an
// offset from its key, in the volume's slice at this frame's time (taken on the CPU by
// detail_noise_slice_rg: one bilinear 2D fetch here instead of a trilinear 3D one, the
// volume's time axis shared by all particles; dust and smoke read channel r, fire channel g).
flat in vec3 v_center;
flat in float v_radius;
flat in vec4 v_color_tau;
flat in vec4 v_medium;  // temperature, opacity, medium, detail key
#if LIT == 1
flat in vec4 v_light;   // the others' optical depth at the centre, its gradient (view space)
#elif LIT == 2
// Every particle: view-space centre and radius, then its extinction through the centre.
layout(std430, binding = 5) readonly buffer Casters { vec4 u_casters[]; };
uniform int u_caster_count;
// Every fire particle: view-space position and radius, then its intensity.
layout(std430, binding = 6) readonly buffer FireEmitters { vec4 u_fire_emitters[]; };
uniform int u_fire_emitter_count;
// The meshes' shadow (systems/shadowing/mesh_shadow_map.h), sampled per fragment.
uniform int u_mesh_shadowed;
uniform sampler2DShadow u_mesh_shadow;
uniform mat4 u_mesh_shadow_transform;     // view position -> its texture coordinates and depth
uniform float u_mesh_shadow_texel_depth;  // a texel's side in its depth units
uniform float u_mesh_shadow_max_depth;    // -ln of the deepest shadow (kMeshShadowDepth)
#endif
#if LIT == 1
flat in vec3 v_fire;    // the clustered fire lights' in-scattered radiance at the centre
#endif

layout(binding = 1) uniform sampler2D u_scene_depth;  // window depth of the opaque scene
uniform vec2 u_depth_scale;     // scene-depth texels per target pixel
uniform vec2 u_viewport;        // target size in pixels (a cell of the media atlas, or all of it)
uniform vec2 u_target_origin;   // its lower-left corner in the framebuffer
uniform vec4 u_projection_terms;  // P[0][0], P[1][1], P[2][0], P[2][1] (off-axis terms)
uniform float u_near;
uniform float u_far;

layout(binding = 3) uniform sampler1D u_blackbody;  // emitted radiance over [T_min, T_max]
layout(binding = 4) uniform sampler2D u_detail;     // periodic noise slice in [0, 1], rg
// The key light and the ambient term (lights.glsl); E is the key light's radiance times the
// shading's light scale.
#include "lights.glsl"
#if SHADING == 1
flat in vec3 v_light_view;     // the way the key light travels, view space, unit
#endif
uniform float u_light_scale;
uniform float u_albedo;
uniform float u_g;
uniform float u_detail_amplitude;
uniform float u_detail_frequency;
uniform vec4 u_fire;            // T_min, T_max, scale, bias
uniform float u_fire_detail_range;

layout(location = 0) out vec4 o_color;

// Texture coordinate of node value x on a table with `n` nodes over [lo, hi] (texel centres on
// the nodes).
float node_coord(float x, float lo, float hi, float n) {
  return (clamp((x - lo) / (hi - lo), 0.0, 1.0) * (n - 1.0) + 0.5) / n;
}

#include "cornette_shanks.glsl"
#if LIT
#include "fire_light.glsl"
#endif

#if LIT == 2
// The optical depth toward the light from view-space point x: every particle's chord beyond x,
// times its extinction along that line (engine/math/sphere_line_integral.h's
// sphere_optical_depth over [0, infinity), summed).
float exact_depth_to_light(vec3 x, vec3 toward_light) {
  float total = 0.0;
  for (int j = 0; j < u_caster_count; ++j) {
    vec4 cr = u_casters[2 * j];
    vec3 v = cr.xyz - x;
    float tc = dot(v, toward_light);
    float d2 = max(dot(v, v) - tc * tc, 0.0);
    if (d2 >= cr.w * cr.w) continue;
    float h = sqrt(cr.w * cr.w - d2);
    float inside = tc + h - max(tc - h, 0.0);
    if (inside > 0.0) total += u_casters[2 * j + 1].x * (1.0 - sqrt(d2) / cr.w) * inside;
  }
  return total;
}
#endif

#if LIT == 2
// How much of the key light passes the meshes to view-space point x (one texel's depth of bias).
float mesh_visibility(vec3 x) {
  if (u_mesh_shadowed == 0) return 1.0;
  vec3 t = (u_mesh_shadow_transform * vec4(x, 1.0)).xyz;
  return textureLod(u_mesh_shadow, vec3(t.xy, t.z - u_mesh_shadow_texel_depth), 0.0);
}

// The fire's in-scattered radiance at view-space point x (before the albedo), seen along to_eye:
// every fire particle (fire_light.glsl).
vec3 fire_inscattered(vec3 x, vec3 to_eye, float g) {
  vec3 sum = vec3(0.0);
  for (int j = 0; j < u_fire_emitter_count; ++j)
    sum += fire_light_inscattered(u_fire_emitters[2 * j], u_fire_emitters[2 * j + 1].rgb, x, to_eye, g);
  return sum;
}
#endif

float view_depth(float window_depth) {
  float z_ndc = window_depth * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - z_ndc * (u_far - u_near));
}

void main() {
  vec2 frag = gl_FragCoord.xy - u_target_origin;  // in the target
  vec2 ndc = frag / u_viewport * 2.0 - 1.0;
  // The ray through this pixel, scaled so that its parameter is the view depth.
  vec3 dir = vec3((ndc.x + u_projection_terms.z) / u_projection_terms.x,
                  (ndc.y + u_projection_terms.w) / u_projection_terms.y, -1.0);
  vec3 p = v_center;
  float r = v_radius;
  float a = dot(dir, dir);
  float b = dot(dir, p);
  float c = dot(p, p) - r * r;
  float distance2 = max(dot(p, p) - b * b / a, 0.0);  // squared distance of the ray from p
  if (distance2 >= r * r) discard;
  float d = sqrt(distance2);
  float ds;
  float enter_depth = 0.0, leave_depth = 0.0, scene_depth = 0.0;
#if PLANAR
  // The planar billboard: the full chord, wherever the plane is.
  ds = 2.0 * sqrt(r * r - distance2);
#else
  {
    float h = sqrt(max(b * b - a * c, 0.0));
    float enter = (b - h) / a, leave = (b + h) / a;  // view depths
    float scene = view_depth(texelFetch(u_scene_depth, ivec2(frag * u_depth_scale), 0).r);
    enter_depth = enter;
    leave_depth = leave;
    scene_depth = scene;
    float from = max(enter, u_near), to = min(leave, scene);
    ds = max(to - from, 0.0) * sqrt(a);  // view depth to path length
  }
#endif
#if SHADING == 0
  float alpha = 1.0 - exp(-v_color_tau.a * (1.0 - d / r) * ds);
  o_color = vec4(v_color_tau.rgb * alpha, alpha);
#else
  // The particle's detail window: the ray's closest point to the centre, in units of r,
  // scaled, offset by the particle's key; the slice moves in time.
  float key = v_medium.w;
  vec3 closest = dir * (b / a) - p;
  vec2 window = closest.xy / r * u_detail_frequency + vec2(key, fract(key * 7.0));
#if SHADING == 2
  float n = texture(u_detail, window).g;
#else
  float n = texture(u_detail, window).r;
#endif
  float tau = v_color_tau.a * v_medium.y;  // density times the opacity curve
  float alpha = 1.0 - exp(-tau * (1.0 - d / r) * ds);
#if SHADING == 2
  float T = u_fire.w + u_fire.z * (v_medium.x + u_fire_detail_range * (n - 0.5));
  vec3 emitted = texture(u_blackbody, node_coord(T, u_fire.x, u_fire.y,
                                                 float(textureSize(u_blackbody, 0)))).rgb;
  o_color = vec4(emitted * alpha, alpha);  // a = 0: alpha L_e
#else
  alpha = clamp(alpha * (1.0 + u_detail_amplitude * (2.0 * n - 1.0)), 0.0, 1.0);
  vec3 to_eye = -normalize(dir);
  float mu = dot(v_light_view, to_eye);  // photon's direction before and after scattering
  float phase = cornette_shanks(mu, u_g);
  // Light's path inside the sphere, from the middle of the visible segment towards the light.
#if PLANAR
  float middle = b / a;
#else
  float middle = 0.5 * (max(enter_depth, u_near) + min(leave_depth, scene_depth));
#endif
  vec3 m = dir * middle - p;
  float mb = dot(m, -v_light_view);
  float chord = max(-mb + sqrt(max(mb * mb - dot(m, m) + r * r, 0.0)), 0.0);
#if LIT == 1
  float light_d = sqrt(max(dot(m, m) - mb * mb, 0.0));  // the light's ray from the centre
  float own = tau * max(1.0 - light_d / r, 0.0) * chord;
  float light_depth = max(v_light.x + dot(v_light.yzw, m), 0.0) + own;
#elif LIT == 2
  float light_depth = exact_depth_to_light(dir * middle, -v_light_view) - log(max(mesh_visibility(dir * middle), exp(-u_mesh_shadow_max_depth)));
#else
  float light_depth = tau * chord;
#endif
  precise vec3 irradiance = key_radiance() * u_light_scale;  // E
  vec3 C = irradiance * phase * exp(-light_depth) + ambient_light();
#if LIT == 1
  C += v_fire;
#elif LIT == 2
  C += fire_inscattered(dir * middle, to_eye, u_g);
#endif
  o_color = vec4(alpha * u_albedo * C, alpha);  // L_e = 0
#endif  // SHADING == 2
#endif  // SHADING == 0
}
