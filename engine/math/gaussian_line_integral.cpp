#include "engine/math/gaussian_line_integral.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>

namespace pyro {

namespace {
constexpr double kExtent = 3.0;  // the kernel's half-width in standard deviations
}  // namespace

ClampedGaussian clamped_gaussian(const glm::dvec3& centre, double radius, double density) {
  ClampedGaussian g;
  g.c = centre;
  g.s = radius / kExtent;
  const double rho = std::min(density, 1.0 - 1e-12);
  const double tau0 = -std::log1p(-rho);
  // Optical depth through the centre of the clamped kernel: k s sqrt(2 pi) erf(3 / sqrt 2).
  g.k = tau0 / (g.s * std::sqrt(2.0 * std::numbers::pi) * std::erf(kExtent / std::numbers::sqrt2));
  return g;
}

bool gaussian_cube_span(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                        double& a, double& b) {
  // The slab method (Kay & Kajiya 1986) against the cube of half-width 3 s.
  const double h = kExtent * g.s;
  a = -1e300;
  b = 1e300;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = g.c[axis] - h, hi = g.c[axis] + h;
    if (w[axis] == 0.0) {
      if (o[axis] < lo || o[axis] > hi) return false;
      continue;
    }
    double ta = (lo - o[axis]) / w[axis], tb = (hi - o[axis]) / w[axis];
    if (ta > tb) std::swap(ta, tb);
    a = std::max(a, ta);
    b = std::min(b, tb);
  }
  return a < b;
}

double gaussian_depth_between(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                              double a, double b) {
  const glm::dvec3 oc = g.c - o;
  const double tc = glm::dot(oc, w);
  const double d2 = glm::dot(oc, oc) - tc * tc;
  const double q = 1.0 / (g.s * std::numbers::sqrt2);
  return g.k * std::exp(-std::max(d2, 0.0) / (2.0 * g.s * g.s)) * g.s *
         std::sqrt(std::numbers::pi / 2.0) * (std::erf((b - tc) * q) - std::erf((a - tc) * q));
}

double GaussianRayProfile::cumulative(double t) const { return amplitude * std::erf((t - tc) * q); }

GaussianRayProfile gaussian_ray_profile(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w) {
  const glm::dvec3 oc = g.c - o;
  GaussianRayProfile p;
  p.tc = glm::dot(oc, w);
  const double d2 = glm::dot(oc, oc) - p.tc * p.tc;
  p.q = 1.0 / (g.s * std::numbers::sqrt2);
  p.amplitude = g.k * std::exp(-std::max(d2, 0.0) / (2.0 * g.s * g.s)) * g.s * std::sqrt(std::numbers::pi / 2.0);
  return p;
}

double gaussian_tail_fraction(double x) {
  const double edge = std::erf(kExtent / std::numbers::sqrt2);
  const double inside = std::clamp(x, -kExtent, kExtent);
  return (edge - std::erf(inside / std::numbers::sqrt2)) / (2.0 * edge);
}

std::array<double, kTailPolynomialTerms> gaussian_tail_polynomial() {
  // Normal equations of the odd basis t, t^3, ..., t^11 (well conditioned on [-1, 1] at this size),
  // solved by Gaussian elimination with partial pivoting.
  constexpr int n = kTailPolynomialTerms, points = 2001;
  double a[n][n + 1] = {};
  for (int p = 0; p < points; ++p) {
    const double x = -kExtent + 2.0 * kExtent * p / (points - 1), t = x / kExtent;
    const double g = 1.0 - 2.0 * gaussian_tail_fraction(x);
    double basis[n];
    for (int k = 0; k < n; ++k) basis[k] = std::pow(t, 2 * k + 1);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) a[r][c] += basis[r] * basis[c];
      a[r][n] += basis[r] * g;
    }
  }
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    std::swap(a[col], a[pivot]);
    for (int r = 0; r < n; ++r) {
      if (r == col) continue;
      const double f = a[r][col] / a[col][col];
      for (int c = col; c <= n; ++c) a[r][c] -= f * a[col][c];
    }
  }
  std::array<double, n> coefficients{};
  for (int k = 0; k < n; ++k) coefficients[size_t(k)] = a[k][n] / a[k][k];
  return coefficients;
}

double evaluate_tail_polynomial(const std::array<double, kTailPolynomialTerms>& c, double x) {
  const double t = std::clamp(x, -kExtent, kExtent) / kExtent, t2 = t * t;
  double p = c.back();
  for (int k = kTailPolynomialTerms - 2; k >= 0; --k) p = p * t2 + c[size_t(k)];
  return 0.5 - 0.5 * p * t;
}

double gaussian_optical_depth(const ClampedGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                              double a, double b) {
  double ca, cb;
  if (!gaussian_cube_span(g, o, w, ca, cb)) return 0.0;
  a = std::max(a, ca);
  b = std::min(b, cb);
  return b > a ? gaussian_depth_between(g, o, w, a, b) : 0.0;
}

}  // namespace pyro
