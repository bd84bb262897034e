#version 450 core
// The optical depth of one anisotropic Gaussian particle along the pixel's ray from the eye,
// in closed form: engine/math/anisotropic_optical_depth.h (anisotropic_ray_segment and
// AnisotropicRaySegment::depth over t in [0, infinity)), evaluated here step for step in float.
// The ray is the eye towards the pixel's point on the far plane (the inverse view-projection,
// applied at the quad's corners and interpolated: anisotropic_splat.vert), so a camera inside a
// particle sees the particle's density ahead of it, not a flat card.
// erf is Abramowitz & Stegun 7.1.26 (|error| <= 1.5e-7), its coefficients the uniform
// u_erf = kErfAs7126 {p, a1, a2, a3, a4, a5} from the same header.
// Output is premultiplied (colour alpha, alpha), alpha = 1 - exp(-tau); blending is
// (ONE, ONE_MINUS_SRC_ALPHA), back to front. A particle that emits (a fire's black-body light,
// engine/math/temperature_emission.h) adds L_e alpha, lit or not: a Gaussian emitter with the
// footprint of its own extinction (Max 1995, absorption plus emission).
//
// LIT: the colour is the albedo times the light reaching the particle along the pixel's ray,
// averaged over the particle's density there (two points, below):
//   L(p) = sun S(mu, tau_others(c) + grad . (p - c) + tau_self(p)) + ambient,
// tau_others and its gradient the light phase's (components/particle_light.h), tau_self(p) the
// particle's own depth from p toward the sun in the same closed form (the segment from
// u0 = M (p - c) along M toward_sun, over [0, infinity)), S the sun's scattering towards the eye
// (sun_scattering.glsl), mu per pixel. One point, the densest, would shade a particle thick
// toward the sun as dark as its core, where the truth averages exp(-tau) over its depth.
#ifndef LIT
#define LIT 0
#endif
noperspective in vec3 v_ray;           // d: the ray's direction, unnormalised
noperspective in vec3 v_ray_whitened;  // M d, M = S^-1 R^T
flat in vec3 v_eye_whitened;           // u0 = M (eye - c)
flat in vec4 v_color_extinction;
flat in vec3 v_emission;

uniform float u_erf[6];
#if LIT
flat in vec4 v_others_depth;  // the others' depth toward the sun at the centre (x), its gradient (yzw)
flat in vec3 v_eye_offset;    // eye - c
flat in vec3 v_sun_whitened;  // M toward_sun
flat in vec3 v_key_toward;    // the key light (lights.glsl) and the ambient light, per
flat in vec3 v_key_radiance;  // particle: uniform reads in each fragment cost more
flat in vec3 v_ambient;
uniform float u_self_shadow;  // 1: shadowed; 0: lit without shadows
uniform int u_octaves;
uniform vec4 u_scattering;
#include "sun_scattering.glsl"
#endif

layout(location = 0) out vec4 o_color;

const float kExtent = 3.0;  // engine/particles/anisotropic_gaussian.h: kAnisotropicExtent
const float kPi = 3.14159265358979;

float erf_as_7_1_26(float x) {
  float ax = abs(x);
  float t = 1.0 / (1.0 + u_erf[0] * ax);
  float poly = t * (u_erf[1] + t * (u_erf[2] + t * (u_erf[3] + t * (u_erf[4] + t * u_erf[5]))));
  float y = 1.0 - poly * exp(-ax * ax);
  return x < 0.0 ? -y : y;
}

#if LIT
// The sun's whitened way, s = M toward_sun, and what the particle's own depth toward the sun
// needs of it, the same for every point of the fragment.
struct SunSegment {
  float inv_a;  // 1 / |s|^2
  float rate;   // sqrt(|s|^2 / 2)
  float scale;  // sqrt(pi / (2 |s|^2))
};
SunSegment sun_segment() {
  float a = dot(v_sun_whitened, v_sun_whitened);
  return SunSegment(1.0 / a, sqrt(0.5 * a), sqrt(kPi / (2.0 * a)));
}

// The particle's own optical depth from the point whose whitened coordinates are u toward the sun
// (AnisotropicRaySegment::depth(0, infinity) of the segment from u along M toward_sun), peak
// extinction k.
float own_depth_toward_sun(vec3 u, float k, SunSegment s) {
  float e2 = kExtent * kExtent;
  float t_c = -dot(u, v_sun_whitened) * s.inv_a;
  vec3 nearest = u + t_c * v_sun_whitened;
  float m2 = dot(nearest, nearest);
  if (!(m2 < e2)) return 0.0;
  float h = sqrt((e2 - m2) * s.inv_a);
  float from = max(0.0, t_c - h), to = t_c + h;
  if (!(to > from)) return 0.0;
  return k * exp(-0.5 * m2) * s.scale * (erf_as_7_1_26(s.rate * (to - t_c)) - erf_as_7_1_26(s.rate * (from - t_c)));
}
#endif

void main() {
  // anisotropic_ray_segment, with w = d / |d| and so v = M w = (M d) / |d|:
  vec3 v = v_ray_whitened / length(v_ray);
  float a = dot(v, v);
  float t_closest = -dot(v_eye_whitened, v) / a;
  vec3 closest = v_eye_whitened + t_closest * v;
  float m2_min = dot(closest, closest);
  float e2 = kExtent * kExtent;
  if (!(m2_min < e2)) discard;
  float h = sqrt((e2 - m2_min) / a);
  float t_enter = t_closest - h, t_exit = t_closest + h;
  float rate = sqrt(0.5 * a);
  float peak = v_color_extinction.a * exp(-0.5 * m2_min) * sqrt(kPi / (2.0 * a));
  // AnisotropicRaySegment::depth(0, infinity):
  float lo = max(0.0, t_enter), hi = t_exit;
  if (!(hi > lo)) discard;
  float tau = peak * (erf_as_7_1_26(rate * (hi - t_closest)) - erf_as_7_1_26(rate * (lo - t_closest)));
  float alpha = 1.0 - exp(-tau);
#if LIT
  // The light averaged over the particle's density along the ray, which is a normal profile in t
  // about t_closest with variance 1 / a: two-point Gauss-Hermite quadrature (nodes at +-1
  // standard deviation, weights 1/2; exact for cubics), nodes kept to the visible chord.
  vec3 w = v_ray / length(v_ray);
  float mu = dot(w, v_key_toward), spread = sqrt(1.0 / a);
  SunSegment sun = sun_segment();
  vec2 tau_nodes;
  for (int node = 0; node < 2; ++node) {
    float t_node = clamp(t_closest + float(2 * node - 1) * spread, lo, hi);
    vec3 offset = v_eye_offset + t_node * w;
    float tau_self = own_depth_toward_sun(v_eye_whitened + t_node * v, v_color_extinction.a, sun);
    tau_nodes[node] = max(u_self_shadow * (v_others_depth.x + dot(v_others_depth.yzw, offset) + tau_self), 0.0);
  }
  vec3 light = v_ambient + v_key_radiance * sun_scattering_mean(mu, tau_nodes);
  o_color = vec4((v_color_extinction.rgb * light + v_emission) * alpha, alpha);
#else
  o_color = vec4((v_color_extinction.rgb + v_emission) * alpha, alpha);
#endif
}
