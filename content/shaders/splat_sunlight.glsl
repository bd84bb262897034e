// The sun's light scattered toward the eye at a point of a lit splat, per unit of the key light's
// radiance (billboard.vert and billboard.frag, LIT 1 and 2; docs/lighting.md): at p = centre +
// offset,
//   S(mu, tau_others(c) + grad . offset + tau_self(p)),
// S one isotropic octave exp(-tau) (LIT 1) or the lobe and octaves (LIT 2, sun_scattering.glsl),
//   tau_self(p) = tau0 exp(-d_perp^2 / (2 s^2)) tail(d_par / s),
// tau0 = -ln(1 - rho) the optical depth through the centre, d_par and d_perp the offset along and
// across the direction toward the sun, tail the fraction of a line's depth beyond d_par / s
// (engine/math/gaussian_line_integral.h, gaussian_tail_fraction, given as the odd polynomial
// gaussian_tail_polynomial fits to it: a texture lookup costs more than the polynomial).
// The including shader includes lights.glsl (and, for LIT 2, sun_scattering.glsl) first, or
// defines SPLAT_KEY_TOWARD as the key light's direction passed in (a fragment shader: a uniform
// read in each fragment costs more than a flat input).
#ifndef SPLAT_KEY_TOWARD
#define SPLAT_KEY_TOWARD key_toward()
#endif
uniform float u_self_shadow;         // 1: the particle shadows itself; 0: lit without shadows
uniform float u_tail_polynomial[6];  // c_k of t^(2k+1), t = x / 3

// others_depth: the other particles' depth at the centre and its gradient; self: tau0, 1 / s,
// 1 / (2 s^2).
float splat_optical_depth(vec3 offset, vec4 others_depth, vec3 self) {
  float d_par = dot(offset, SPLAT_KEY_TOWARD);
  float d_perp2 = max(dot(offset, offset) - d_par * d_par, 0.0);
  float t = clamp(d_par * self.y, -3.0, 3.0) / 3.0, t2 = t * t;
  float p = u_tail_polynomial[5];
  for (int k = 4; k >= 0; --k) p = p * t2 + u_tail_polynomial[k];
  float tail = 0.5 - 0.5 * p * t;
  float tau_self = self.x * exp(-d_perp2 * self.z) * tail;
  return u_self_shadow * (others_depth.x + dot(others_depth.yzw, offset) + tau_self);
}

// mu: the cosine between the sunlight's way and the way to the eye (LIT 2 only).
float splat_sunlight(vec3 offset, vec4 others_depth, vec3 self, float mu) {
  float tau = max(splat_optical_depth(offset, others_depth, self), 0.0);
#if LIT == 2
  return sun_scattering(mu, tau);
#else
  return exp(-tau);
#endif
}
