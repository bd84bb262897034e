#version 450 core
// Instanced particle billboards (Johnson & McAllister 2005, 2.2.1 and section 3). One instance
// per particle, back to front; the four corners come from gl_VertexID (triangle strip).
//  - facing the viewplane: every billboard of an eye shares the camera's right and up axes;
//  - facing the viewpoint: each billboard turns to the eye. Its right axis is the camera's up
//    crossed with the direction to the eye, u = up x (V - C) normalised (paper section 3.1),
//    and its up axis completes the frame. The same construction is
//    engine/math/billboard_alignment.h's viewpoint_facing_axes (reference up = the camera's up,
//    fallback = the camera's right), tested there and, against this shader's images, in
//    tests/render/billboard_alignment_render_test.cpp.
// Vertex pulling: instance k is the particle draw_order[k], whose record is two vec4s
// (packed by systems/billboard_render/billboard_renderer.cpp): world xyz and radius, then
// linear rgb and density rho. The order's entries are u_order_stride_offset.x uints apart, the
// index at .y within one: (1, 0) for an order made on the CPU, (4, 2) for the GPU's sorted
// elements (systems/gpu_sorting/gpu_depth_sort.h).
//
// LIT 1 (lit media, docs/lighting.md): the colour is the particle's albedo, and binding 2 holds
// per particle the optical depth toward the sun of the other particles at its centre and its
// gradient (components/particle_light.h); the fragment shader adds the particle's own.
layout(std430, binding = 0) readonly buffer ParticleRecords { vec4 records[]; };
#ifndef LIT
#define LIT 0
#endif
#if LIT
layout(std430, binding = 2) readonly buffer ParticleShadow { vec4 others_depth[]; };
flat out vec4 v_albedo_density;
flat out vec4 v_others_depth;
flat out vec3 v_self;     // tau0 = -ln(1 - rho), 1 / s (s = radius / 3), 1 / (2 s^2)
flat out vec3 v_key_radiance;  // the key light's radiance and the ambient light, for the fragments
flat out vec3 v_ambient;
flat out vec3 v_key_toward;  // for the fragments' own shadow (splat_sunlight.glsl)
out vec3 v_offset;        // the fragment's place on the billboard, from the centre (world units)
#endif
#ifndef SUNLIGHT_AT_VERTICES
#define SUNLIGHT_AT_VERTICES 0
#endif
#if LIT
// The key light, and (LIT 2) the fire's clustered point lights (lights.glsl), each of which
// scatters I p_HG(mu, g) / max(d^2, r^2) toward the eye (the sun's convention, whose light colour
// is its irradiance over 4 pi: systems/runtime/reference/lit_particle_reference.h).
#include "lights.glsl"
#endif
#if LIT
flat out vec3 v_eye_from_centre;  // the eye - the centre: each fragment's own ray (billboard.frag)
flat out vec3 v_centre;
#endif
#if LIT == 2
flat out float v_view_cosine;  // mu: the sunlight's direction of travel . the way to the eye
flat out vec3 v_fire;          // the fire lights' light scattered at the centre toward the eye
uniform vec4 u_scattering;     // Henyey-Greenstein g; the octaves' a, b, c (billboard.frag)
uniform int u_octaves;         // 1: single scattering
#include "sun_scattering.glsl"
#endif
#if SUNLIGHT_AT_VERTICES
// The sun's light at the corner (splat_sunlight.glsl) as the plane through its value at the
// centre whose slopes along the billboard's axes are the secants over one standard deviation
// either side: the fragments between get it interpolated, and the fragment shader's cost is the
// unlit one's and one exponential.
out float v_sunlight;
#include "splat_sunlight.glsl"
#endif
layout(std430, binding = 1) readonly buffer DrawOrder { uint draw_order[]; };
uniform uvec2 u_order_stride_offset;

uniform mat4 u_view_projection;
uniform vec3 u_right;
uniform vec3 u_up;
uniform vec3 u_eye;
uniform int u_face_viewpoint;
// Maps the billboard's edge-to-edge coordinate s in [0, 1] to the texture coordinate of the
// footprint table's first and last nodes (engine/math/footprint.h, footprint_texcoord).
uniform vec2 u_texcoord_bias_scale;

out vec2 v_texcoord;
flat out vec4 v_premultiplied;  // (rgb * rho, rho): one value per billboard, not interpolated

void main() {
  uint particle = draw_order[uint(gl_InstanceID) * u_order_stride_offset.x + u_order_stride_offset.y];
  vec4 a_center_radius = records[2u * particle];
  vec4 a_color_density = records[2u * particle + 1u];
  vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
  vec3 center = a_center_radius.xyz;
  vec3 right = u_right;
  vec3 up = u_up;
  if (u_face_viewpoint != 0) {
    vec3 to_eye = u_eye - center;
    float distance = length(to_eye);
    // A particle at the eye itself keeps the viewplane axes.
    if (distance > 0.0) {
      vec3 n = to_eye / distance;
      vec3 r = cross(u_up, to_eye);
      // Straight above or below the eye: the camera's right, made normal to n.
      if (length(r) <= 64.0 * 1.1920929e-7 * distance) r = u_right - dot(u_right, n) * n;
      right = normalize(r);
      up = cross(n, right);
    }
  }
  vec3 world = center + (right * corner.x + up * corner.y) * a_center_radius.w;
  v_texcoord = u_texcoord_bias_scale.x + (corner * 0.5 + 0.5) * u_texcoord_bias_scale.y;
  v_premultiplied = vec4(a_color_density.rgb * a_color_density.a, a_color_density.a);
#if LIT
  v_albedo_density = a_color_density;
  v_others_depth = others_depth[particle];
  float s = a_center_radius.w / 3.0;
  v_self = vec3(-log(max(1.0 - a_color_density.a, 1e-12)), 1.0 / s, 0.5 / (s * s));
  v_offset = world - center;
  v_key_radiance = key_radiance();
  v_ambient = ambient_light();
  v_key_toward = key_toward();
  v_eye_from_centre = u_eye - center;
  v_centre = center;
#endif
#if LIT == 2
  vec3 to_eye = u_eye - center;
  vec3 eye_way = length(to_eye) > 0.0 ? normalize(to_eye) : vec3(0.0);
  v_view_cosine = length(to_eye) > 0.0 ? -dot(key_toward(), eye_way) : 1.0;
#else
  float v_view_cosine = 1.0;
#endif
#if SUNLIGHT_AT_VERTICES
  vec3 along_right = right * s, along_up = up * s;
  float at_centre = splat_sunlight(vec3(0.0), v_others_depth, v_self, v_view_cosine);
  float across_right = splat_sunlight(along_right, v_others_depth, v_self, v_view_cosine) -
                       splat_sunlight(-along_right, v_others_depth, v_self, v_view_cosine);
  float across_up = splat_sunlight(along_up, v_others_depth, v_self, v_view_cosine) -
                    splat_sunlight(-along_up, v_others_depth, v_self, v_view_cosine);
  // corner * radius is 3 s along each axis: the secant over 2 s, times 3 s.
  v_sunlight = at_centre + 1.5 * (across_right * corner.x + across_up * corner.y);
#endif
#if LIT == 2
  v_fire = vec3(0.0);
  float g = u_scattering.x;
  for (int j = 0; j < fire_light_count(); ++j) {
    FireLightPath path = fire_light_path(j, center);
    v_fire += fire_light(j, path, henyey_greenstein(fire_light_cosine(path, eye_way), g));
  }
#endif
  gl_Position = u_view_projection * vec4(world, 1.0);
}
