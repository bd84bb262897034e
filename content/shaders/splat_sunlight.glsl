// The sun's light scattered toward the eye at a point of a lit splat, per unit of the key light's
// radiance (billboard.vert and billboard.frag, LIT 1 and 2; docs/lighting.md): at p = centre +
// offset,
//   S(mu, tau_others(c) + grad . offset + tau_self(p)),
// S one isotropic octave exp(-tau) (LIT 1) or the lobe and octaves (LIT 2, sun_scattering.glsl),
//   tau_self(p) = tau0 exp(-d_perp^2 / (2 s^2)) tail(d_par / s),
// tau0 = -ln(1 - rho) the optical depth through the centre, d_par and d_perp the offset along and
// across the direction toward the sun, tail the fraction of a line's depth beyond d_par / s
// (engine/math/gaussian_line_integral.h, gaussian_tail_fraction, given as the odd polynomial
// gaussian_tail_polynomial fits to it: a texture lookup costs more than the polynomial), or the
// opacity map's depth at p where the including shader defines SPLAT_SUNLIGHT_MAP.
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

// The sun's term at optical depth tau toward it; mu: the cosine between the sunlight's way and
// the way to the eye (LIT 2 only).
float splat_sun_term(float tau, float mu) {
  tau = max(tau, 0.0);
#if LIT == 2
  return sun_scattering(mu, tau);
#else
  return exp(-tau);
#endif
}

float splat_sunlight(vec3 offset, vec4 others_depth, vec3 self, float mu) {
  return splat_sun_term(splat_optical_depth(offset, others_depth, self), mu);
}

#ifdef SPLAT_SUNLIGHT_MAP
// The light of particles in a draw that holds a thick one (billboard.frag, THICK_PARTICLES: an
// optical depth through its centre of 1 or more), where the depth across one particle is large
// and its linearization about the centre fails: white on the sunward side, where it goes
// negative, far too deep on the other.
//
// The sun's term at p. With the opacity map bound (u_shadowed; the including shader declares it,
// u_shadow_map, holding the transmittance, u_world_to_shadow and SPLAT_CENTRE, the particle's
// centre), from the map's transmittance read where p is: every particle's, this one's included
// (one isotropic octave is the transmittance itself). Otherwise from the linearization.
float splat_seen_sun_term(vec3 offset, vec4 others_depth, vec3 self, float mu) {
  if (u_shadowed == 0) return splat_sun_term(splat_optical_depth(offset, others_depth, self), mu);
  vec3 texcoord = (u_world_to_shadow * vec4(SPLAT_CENTRE + offset, 1.0)).xyz;
  float transmittance = u_self_shadow > 0.0 ? max(texture(u_shadow_map, texcoord).r, 1e-30) : 1.0;
#if LIT == 2
  return sun_scattering(mu, -log(transmittance));
#else
  return transmittance;
#endif
}

// The standard normal's quantile, Phi^-1(v) (Abramowitz & Stegun 26.2.23, |error| < 4.5e-4):
// engine/math/normal_quantile.h's normal_quantile, tested there.
float normal_quantile(float v) {
  float q = clamp(min(v, 1.0 - v), 1e-30, 0.5);
  float y = sqrt(-2.0 * log(q));
  float u = y - (2.515517 + y * (0.802853 + y * 0.010328)) / (1.0 + y * (1.432788 + y * (0.189269 + y * 0.001308)));
  return v < 0.5 ? -u : u;
}

// The sunlight where the eye sees the particle along the pixel's ray. Along the ray the
// particle's extinction is a normal profile about the closest approach `closest`; with tau the
// column's depth at this pixel, the light the eye receives from depth u (in standard deviations,
// away from the eye) is weighted by tau phi(u) exp(-tau Phi(u)), in v = Phi(u) an exponential
// truncated to [0, 1]. The sunlight is averaged over its quartiles, the v with
// 1 - e^-(tau v) = q (1 - e^-tau), q = 1/4 and 3/4: a dense particle is lit where the eye meets
// it, on its near side (engine/math/normal_quantile.h, seen_depth, tested there). One point, the
// median, leaves the mean of exp(-tau) over a particle whose light varies across it too dark
// (Jensen's inequality), and more so as the map resolves that variation.
float splat_sunlight_seen(vec3 closest, vec3 ray, float tau, vec4 others_depth, vec3 self, float mu) {
  float seen = 1.0 - exp(-tau), sum = 0.0;
  for (int k = 0; k < 2; ++k) {
    float q = k == 0 ? 0.25 : 0.75;
    float v = tau > 1e-4 ? -log(1.0 - q * seen) / tau : q;
    vec3 p = closest + ray * (normal_quantile(v) / self.y);
    sum += splat_seen_sun_term(p, others_depth, self, mu);
  }
  return 0.5 * sum;
}
#endif
