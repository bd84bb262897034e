#pragma once
// The standard normal distribution's quantile, Phi^-1(v): the u with Phi(u) = v. Abramowitz &
// Stegun 26.2.23, a rational function of y = sqrt(-2 ln q), q = min(v, 1 - v), with
// |error| < 4.5e-4 for 0 < v < 1. content/shaders/splat_sunlight.glsl evaluates the same function
// to place a lit splat's sunlight where the eye sees it (splat_sunlight_seen).
#include <algorithm>
#include <cmath>

namespace pyro {

inline double normal_quantile(double v) {
  const double q = std::clamp(std::min(v, 1.0 - v), 1e-30, 0.5);
  const double y = std::sqrt(-2.0 * std::log(q));
  const double u = y - (2.515517 + y * (0.802853 + y * 0.010328)) /
                           (1.0 + y * (1.432788 + y * (0.189269 + y * 0.001308)));
  return v < 0.5 ? -u : u;
}

// Where the eye sees a Gaussian of column depth tau along its ray, in standard deviations from
// its centre toward the far side: the quantile q of the light it sends (weight tau phi(u)
// exp(-tau Phi(u)), the part of the column in front of u hiding the rest), at
// Phi(u) = -ln(1 - q (1 - e^-tau)) / tau. The median (q = 1/2) is 0 for a thin particle and
// tends to -3 as tau grows.
inline double seen_depth(double tau, double q = 0.5) {
  if (!(tau > 1e-4)) return normal_quantile(q);
  return normal_quantile(-std::log1p(-q * -std::expm1(-tau)) / tau);
}

}  // namespace pyro
