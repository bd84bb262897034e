#pragma once
// The optical depth of one Gaussian particle along a straight line, in closed form: what the CPU
// references integrate along view rays and what the light phase integrates along shadow rays.
//
// Particle (centre c, radius r, density rho) is the extinction field
//   sigma(p) = k exp(-|p - c|^2 / (2 s^2)),  s = r / 3,
// clamped to the cube |p - c|_inf <= 3 s (engine/math/footprint.h: the kernel is clamped to
// [-3, 3] on every axis), with k chosen so that the optical depth through the centre is
// tau0 = -ln(1 - rho): the splat's opacity at its centre, 1 - exp(-tau0) = rho, is matched.
// Along a ray o + t w (|w| = 1) its optical depth over [a, b] is, with tc the closest approach
// and d the miss distance (Abramowitz & Stegun 7.1.1):
//   k exp(-d^2 / (2 s^2)) s sqrt(pi / 2) [erf((b - tc) / (s sqrt 2)) - erf((a - tc) / (s sqrt 2))].
#include <array>

#include <glm/vec3.hpp>

namespace pyro {

// The particle's cube, the support of the clamped Gaussian: its half-width in standard
// deviations, and how far it reaches from its centre in any direction, its half-diagonal
// 3 sqrt 3 (what a projection of it across a light can cover).
inline constexpr double kGaussianCubeHalfWidth = 3.0;
inline constexpr double kGaussianCubeReach = kGaussianCubeHalfWidth * 1.7320508075688772;

struct ClampedGaussian {
  glm::dvec3 c{0.0};
  double s = 1.0;  // standard deviation: the radius over 3
  double k = 0.0;  // extinction at the centre
};

// The particle of radius `radius` and centre opacity `density` (clamped below 1).
ClampedGaussian clamped_gaussian(const glm::dvec3& centre, double radius, double density);

// Where the ray o + t w is inside the particle's cube: [a, b]; false if nowhere.
bool gaussian_cube_span(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                        double& a, double& b);

// The optical depth over [a, b] of the unclamped Gaussian (the closed form above); the caller
// keeps [a, b] inside the cube span.
double gaussian_depth_between(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                              double a, double b);

// The closed form along one ray with what does not depend on [a, b] worked out once: the depth
// over [a, b] is cumulative(b) - cumulative(a) (for many intervals of one ray: one erf each).
struct GaussianRayProfile {
  double tc = 0.0;         // the closest approach
  double amplitude = 0.0;  // k exp(-d^2 / (2 s^2)) s sqrt(pi / 2)
  double q = 1.0;          // 1 / (s sqrt 2)
  double cumulative(double t) const;
};
GaussianRayProfile gaussian_ray_profile(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w);

// The fraction of a clamped Gaussian's optical depth along a line that lies beyond x standard
// deviations from its closest approach (1 at x <= -3, 0 at x >= 3):
//   (erf(3 / sqrt 2) - erf(x / sqrt 2)) / (2 erf(3 / sqrt 2)).
double gaussian_tail_fraction(double x);

// The same as an odd polynomial for shaders: with t = clamp(x, -3, 3) / 3,
//   tail(x) ~ 0.5 - 0.5 sum_k c[k] t^(2k+1),
// c the least-squares fit on 2001 points over [-3, 3] (max error 1.1e-4, tested).
inline constexpr int kTailPolynomialTerms = 6;
std::array<double, kTailPolynomialTerms> gaussian_tail_polynomial();
double evaluate_tail_polynomial(const std::array<double, kTailPolynomialTerms>& c, double x);

// The optical depth of the clamped particle along o + t w over t in [a, b].
double gaussian_optical_depth(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                              double a, double b);

}  // namespace pyro
