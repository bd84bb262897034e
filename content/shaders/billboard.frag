#version 450 core
// Opacity = density x footprint (Johnson & McAllister eqs. 5-7 with a black kernel texture):
// the kernel texture holds the scaled footprint table, the colour is the particle's own.
// Output is premultiplied; blending is (ONE, ONE_MINUS_SRC_ALPHA), back to front.
//
// LIT 1 and LIT 2: the colour is the albedo times the light reaching the point p where the eye
// sees the particle along the pixel's ray (its closest approach to the centre for a thin particle,
// nearer the eye for a dense one: splat_sunlight_seen):
//   L = key radiance x sunlight(p) + ambient (+ LIT 2: the fire lights' light at the centre,
//   billboard.vert),
// sunlight the sun's scattering toward the eye through the optical depth at p: with the map
// method the opacity map's, read at p (u_shadowed); otherwise the others' depth linearized about
// the centre plus the particle's own (splat_sunlight.glsl). SUNLIGHT_AT_VERTICES: sunlight comes
// interpolated from the billboard's corners, a plane through its value at the centre
// (billboard.vert); otherwise each fragment evaluates it.
#ifndef LIT
#define LIT 0
#endif
#ifndef SUNLIGHT_AT_VERTICES
#define SUNLIGHT_AT_VERTICES 0
#endif
#ifndef THICK_PARTICLES
#define THICK_PARTICLES 0
#endif
in vec2 v_texcoord;
flat in vec4 v_premultiplied;
#if LIT
flat in vec4 v_albedo_density;
flat in vec3 v_self;  // tau0, 1 / s, 1 / (2 s^2)
flat in vec3 v_key_radiance;  // the key light's, and the ambient light (lights.glsl), per
flat in vec3 v_ambient;       // particle: uniform reads in each fragment cost more
#if LIT == 2
flat in vec3 v_fire;          // the fire lights' scattered light, per particle (billboard.vert)
#endif
#if SUNLIGHT_AT_VERTICES
in float v_sunlight;
#else
flat in vec4 v_others_depth;
in vec3 v_offset;
flat in vec3 v_key_toward;
#define SPLAT_KEY_TOWARD v_key_toward
// The eye - the centre: the pixel's ray, and (LIT 2) mu, the sunlight's direction of travel . the
// way to the eye, each fragment's own, as the reference takes them along each pixel's ray; one mu
// per particle would spread a narrow lobe (g near +-1) over the whole billboard.
flat in vec3 v_eye_from_centre;
// The map method's opacity map (systems/lighting/opacity_map_texture.h, the transmittance).
flat in vec3 v_centre;
uniform int u_shadowed;
uniform sampler3D u_shadow_map;
uniform mat4 u_world_to_shadow;
#if THICK_PARTICLES
#define SPLAT_SUNLIGHT_MAP
#endif
#define SPLAT_CENTRE v_centre
#if LIT == 2
uniform int u_octaves;        // 1: single scattering
uniform vec4 u_scattering;    // Henyey-Greenstein g; the octaves' a, b, c
#include "sun_scattering.glsl"
#endif
#include "splat_sunlight.glsl"
#endif
#endif

layout(binding = 0) uniform sampler2D u_kernel;

layout(location = 0) out vec4 o_color;

void main() {
  float footprint = textureLod(u_kernel, v_texcoord, 0.0).r;
#if LIT
  float tau0 = v_self.x;
#if SUNLIGHT_AT_VERTICES
  float sunlight = max(v_sunlight, 0.0);
#else
  // THICK_PARTICLES, for a draw that holds a particle whose optical depth through the centre is 1
  // or more (the renderer's choice): every particle is lit where the eye sees it along the pixel's
  // ray (splat_sunlight_seen). Otherwise each is lit at the fragment's point on the billboard,
  // nearly where the ray passes closest to its centre, from the others' depth linearized about the
  // centre and its own. A branch per particle would cost the thin ones as much: a software
  // rasteriser runs both sides of it for every fragment.
  vec3 to_eye = v_eye_from_centre - v_offset;
  float to_eye2 = dot(to_eye, to_eye);
#if LIT == 2
  float mu = to_eye2 > 0.0 ? -dot(v_key_toward, to_eye) * inversesqrt(to_eye2) : 1.0;
#else
  float mu = 1.0;
#endif
#if THICK_PARTICLES
  vec3 ray = to_eye2 > 0.0 ? -to_eye * inversesqrt(to_eye2) : -v_key_toward;
  float sunlight = splat_sunlight_seen(v_offset - ray * dot(v_offset, ray), ray, tau0 * footprint, v_others_depth, v_self, mu);
#else
  float sunlight = splat_sunlight(v_offset, v_others_depth, v_self, mu);
#endif
#endif
#if LIT == 2
  vec3 light = v_key_radiance * sunlight + v_ambient + v_fire;
#else
  vec3 light = v_key_radiance * sunlight + v_ambient;
#endif
  // The opacity of the Gaussian's column through this point, 1 - exp(-tau0 f), f the footprint
  // scaled to 1 at the centre: rho at the centre as in the unlit splats, and the exact opacity
  // elsewhere (the unlit splats' rho f follows Johnson & McAllister's eq. 5, thinner off-centre).
  float alpha = 1.0 - exp(-tau0 * footprint);
  o_color = vec4(v_albedo_density.rgb * light * alpha, alpha);
#else
  o_color = v_premultiplied * footprint;
#endif
}
