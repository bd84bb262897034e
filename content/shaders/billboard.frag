#version 450 core
// Opacity = density x footprint (Johnson & McAllister eqs. 5-7 with a black kernel texture):
// the kernel texture holds the scaled footprint table, the colour is the particle's own.
// Output is premultiplied; blending is (ONE, ONE_MINUS_SRC_ALPHA), back to front.
//
// LIT 1 and LIT 2: the colour is the albedo times the light reaching the fragment's point p = centre +
// offset (where the pixel's ray passes closest to the centre):
//   L = sun S(mu, tau_others(c) + grad . offset + tau_self(p)) + ambient,
// S the sun's scattering towards the eye (LIT 1: one isotropic octave, exp(-tau); LIT 2: the
// lobe and octaves below, plus the fire lights' light at the centre, billboard.vert),
//   tau_self(p) = tau0 exp(-d_perp^2 / (2 s^2)) tail(d_par / s),
// tau0 = -ln(1 - rho) the optical depth through the centre, d_par and d_perp the offset along and
// across the direction toward the sun, tail the fraction of a line's depth beyond d_par / s
// (engine/math/gaussian_line_integral.h, gaussian_tail_fraction, given as the odd polynomial
// gaussian_tail_polynomial fits to it: a texture lookup here costs more than the polynomial).
#ifndef LIT
#define LIT 0
#endif
in vec2 v_texcoord;
flat in vec4 v_premultiplied;
#if LIT
flat in vec4 v_albedo_density;
flat in vec4 v_others_depth;
flat in vec3 v_self;  // tau0, 1 / s, 1 / (2 s^2)
in vec3 v_offset;
#include "lights.glsl"       // the media are lit by the key light and the ambient term
uniform float u_self_shadow;  // 1: the particle shadows itself; 0: lit without shadows
uniform float u_tail_polynomial[6];  // c_k of t^(2k+1), t = x / 3
#endif
#if LIT == 2
flat in float v_view_cosine;  // mu, per particle
flat in vec3 v_fire;          // the fire lights' scattered light, per particle (billboard.vert)
uniform int u_octaves;        // 1: single scattering
uniform vec4 u_scattering;    // Henyey-Greenstein g; the octaves' a, b, c
#include "sun_scattering.glsl"
#endif

layout(binding = 0) uniform sampler2D u_kernel;

layout(location = 0) out vec4 o_color;

void main() {
  float footprint = textureLod(u_kernel, v_texcoord, 0.0).r;
#if LIT
  float tau0 = v_self.x;
  float d_par = dot(v_offset, key_toward());
  float d_perp2 = max(dot(v_offset, v_offset) - d_par * d_par, 0.0);
  float t = clamp(d_par * v_self.y, -3.0, 3.0) / 3.0, t2 = t * t;
  float p = u_tail_polynomial[5];
  for (int k = 4; k >= 0; --k) p = p * t2 + u_tail_polynomial[k];
  float tail = 0.5 - 0.5 * p * t;
  float tau_self = tau0 * exp(-d_perp2 * v_self.z) * tail;
  float tau = u_self_shadow * (v_others_depth.x + dot(v_others_depth.yzw, v_offset) + tau_self);
#if LIT == 2
  vec3 light = key_radiance() * sun_scattering(v_view_cosine, max(tau, 0.0)) + ambient_light() + v_fire;
#else
  vec3 light = key_radiance() * exp(-max(tau, 0.0)) + ambient_light();
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
