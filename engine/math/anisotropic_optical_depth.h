#pragma once
// The optical depth of one anisotropic Gaussian particle (engine/particles/anisotropic_gaussian.h)
// along a ray, in closed form.
//
// Derivation (ours; the Gaussian line integral as in volumetric Gaussian rendering). Put the ray
// o + t w (|w| = 1) into the particle's whitened frame, where the ellipsoid is the sphere of
// radius 3 (kAnisotropicExtent) about the origin:
//   u(t) = M (o + t w - c) = u0 + t v,   M = S^-1 R^T,  u0 = M (o - c),  v = M w,
// so that m^2(t) = |u(t)|^2 = A t^2 + 2 B t + C with A = |v|^2 = w^T Sigma^-1 w,
// B = u0 . v = w^T Sigma^-1 (o - c) and C = |u0|^2 = (o - c)^T Sigma^-1 (o - c). Completing the
// square about the closest approach t_c = -B / A:
//   m^2(t) = m2_min + A (t - t_c)^2,   m2_min = C - B^2 / A = |u0 + t_c v|^2
// (the last form is the squared distance of the closest point in the whitened frame: it has no
// cancellation, so it is the one evaluated). The ray is inside the ellipsoid m <= 3 on the chord
//   t_c -+ h,  h = sqrt((9 - m2_min) / A)   (none when m2_min >= 9),
// and with x = sqrt(A / 2) (t - t_c), dt = dx / sqrt(A / 2), the integral of k exp(-m^2 / 2)
// over [lo, hi] (the chord cut to [a, b]) is
//   k exp(-m2_min / 2) sqrt(pi / (2 A)) [erf(sqrt(A / 2) (hi - t_c)) - erf(sqrt(A / 2) (lo - t_c))]
// with erf(x) = 2 / sqrt(pi) * integral_0^x exp(-s^2) ds (Abramowitz & Stegun 7.1.1).
// The isotropic case (A = 1 / s^2) is systems/runtime/reference/particle_reference.h's closed form.
//
// The fragment shader content/shaders/anisotropic_splat.frag evaluates the same steps in float,
// with erf replaced by Abramowitz & Stegun 7.1.26 (|error| <= 1.5e-7); its coefficients come from
// kErfAs7126 below, sent as a uniform, so the shader holds no second copy of them.
#include <array>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "engine/particles/anisotropic_gaussian.h"

namespace pyro {

// One particle along one ray: everything the closed form needs, computed once per ray so that
// any sub-interval's optical depth costs two erf.
struct AnisotropicRaySegment {
  bool hit = false;         // the ray's line meets the ellipsoid m <= 3
  double t_enter = 0.0;     // the chord t_c - h .. t_c + h (meaningful when hit)
  double t_exit = 0.0;
  double t_closest = 0.0;   // t_c
  double rate = 0.0;        // sqrt(A / 2)
  double peak = 0.0;        // k exp(-m2_min / 2) sqrt(pi / (2 A))

  // Optical depth over [a, b] cut to the chord; 0 when the ray misses or b <= a.
  double depth(double a, double b) const;
};

// M = S^-1 R^T: maps p - c into the whitened frame (rows: the local axes over their scales).
glm::dmat3 whitening_matrix(const AnisotropicGaussian& g);

// The segment of the line o + t w (|w| = 1) through the particle.
AnisotropicRaySegment anisotropic_ray_segment(const AnisotropicGaussian& g, const glm::dvec3& o,
                                              const glm::dvec3& w);
// The same from the whitened terms, for many rays from one origin: m = whitening_matrix(g),
// u0 = m (o - c), k the peak extinction.
AnisotropicRaySegment anisotropic_ray_segment(const glm::dmat3& m, const glm::dvec3& u0, double k,
                                              const glm::dvec3& w);

// Optical depth of the particle along o + t w (|w| = 1) over t in [a, b], truncated to m <= 3.
double anisotropic_optical_depth(const AnisotropicGaussian& g, const glm::dvec3& o,
                                 const glm::dvec3& w, double a, double b);

// Abramowitz & Stegun 7.1.26: for x >= 0,
//   erf(x) = 1 - (a1 t + a2 t^2 + a3 t^3 + a4 t^4 + a5 t^5) exp(-x^2) + e(x),  t = 1 / (1 + p x),
//   |e(x)| <= 1.5e-7,
// extended to x < 0 by erf(-x) = -erf(x). Stored as {p, a1, a2, a3, a4, a5}.
inline constexpr std::array<double, 6> kErfAs7126 = {0.3275911,    0.254829592,  -0.284496736,
                                                     1.421413741,  -1.453152027, 1.061405429};
inline constexpr double kErfAs7126MaxError = 1.5e-7;

// The approximation above, as the shader evaluates it (in double here).
double erf_as_7_1_26(double x);

}  // namespace pyro
