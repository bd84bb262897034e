// The explosion's spherical particle along a line (engine/math/sphere_line_integral.h) against
// a midpoint sum of its extinction field, and against the closed forms of a ray through the
// centre and of the whole particle's projected optical depth.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/core/rng.h"
#include "engine/math/shadow_caster.h"
#include "engine/math/sphere_line_integral.h"

namespace pyro {
namespace {

constexpr double kSphereLineIntegralInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// The extinction at point x for a ray along w: k (1 - d / r) inside the sphere, d the ray's miss
// distance from the centre.
double extinction_at(const ConeSphere& s, const glm::dvec3& x, const glm::dvec3& w) {
  const glm::dvec3 v = x - s.c;
  if (glm::dot(v, v) >= s.r * s.r) return 0.0;
  const double along = glm::dot(v, w);
  const double d = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0));
  return s.k * (1.0 - d / s.r);
}

TEST(SphereLineIntegral, MatchesAMidpointSumAlongRandomRays) {
  Rng rng(31);
  const ConeSphere s{{0.3, -0.2, 0.5}, 1.3, 2.5};
  int hits = 0;
  for (int n = 0; n < 200; ++n) {
    const glm::dvec3 o(rng.uniform(-3.0f, 3.0f), rng.uniform(-3.0f, 3.0f), rng.uniform(-3.0f, 3.0f));
    // Aimed near the sphere, so that most rays cross it, some miss it and some graze it.
    const glm::dvec3 aim = s.c + glm::dvec3(rng.uniform(-1.6f, 1.6f), rng.uniform(-1.6f, 1.6f),
                                            rng.uniform(-1.6f, 1.6f));
    const glm::dvec3 w = glm::normalize(aim - o);
    const double a = rng.uniform(0.0f, 3.0f), b = a + rng.uniform(0.5f, 6.0f);
    const int steps = 20000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) sum += extinction_at(s, o + (a + (i + 0.5) * (b - a) / steps) * w, w);
    sum *= (b - a) / steps;
    EXPECT_NEAR(sphere_optical_depth(s, o, w, a, b), sum, 2e-3 * (1.0 + sum)) << n;
    hits += sum > 0.0;
  }
  EXPECT_GT(hits, 60);
}

TEST(SphereLineIntegral, ThroughTheCentreIsTheDiameterTimesK) {
  const ConeSphere s{{1.0, 2.0, 3.0}, 0.7, 1.9};
  const glm::dvec3 w = glm::normalize(glm::dvec3(1.0, -2.0, 0.5));
  EXPECT_NEAR(sphere_optical_depth(s, s.c - 5.0 * w, w, -kSphereLineIntegralInf, kSphereLineIntegralInf), 2.0 * 0.7 * 1.9, 1e-12);
  // From the centre outward: half of it; a ray that misses: nothing.
  EXPECT_NEAR(sphere_optical_depth(s, s.c, w, 0.0, kSphereLineIntegralInf), 0.7 * 1.9, 1e-12);
  EXPECT_EQ(sphere_optical_depth(s, s.c + glm::dvec3(0.0, 0.0, 0.71), {1.0, 0.0, 0.0}, -kSphereLineIntegralInf, kSphereLineIntegralInf), 0.0);
}

// Over the disc it projects to, the optical depth integrates to
// k int_0^r (1 - d/r) 2 sqrt(r^2 - d^2) 2 pi d dd = 4 pi k r^3 (1/3 - pi/16).
TEST(SphereLineIntegral, ProjectedDepthIntegratesToTheClosedForm) {
  const ConeSphere s{{0.0, 0.0, 0.0}, 1.5, 0.8};
  const glm::dvec3 w(0.0, 0.0, 1.0);
  const int n = 600;
  const double cell = 2.0 * s.r / n;
  double total = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 o(-s.r + (i + 0.5) * cell, -s.r + (j + 0.5) * cell, -10.0);
      total += sphere_optical_depth(s, o, w, -kSphereLineIntegralInf, kSphereLineIntegralInf) * cell * cell;
    }
  const double want = 4.0 * kPi * s.k * s.r * s.r * s.r * (1.0 / 3.0 - kPi / 16.0);
  EXPECT_NEAR(total, want, 1e-3 * want);
}

// The opacity over the projected disc: a midpoint sum over the disc, and its two limits (nearly
// transparent: k times the projected depth's closed form; opaque: the disc's area).
TEST(SphereLineIntegral, OpacityAreaMatchesTheDiscAndItsLimits) {
  for (const double k : {0.3, 2.0, 9.0}) {
    const ConeSphere s{{0.0, 0.0, 0.0}, 1.2, k};
    const int n = 500;
    const double cell = 2.0 * s.r / n;
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const glm::dvec3 o(-s.r + (i + 0.5) * cell, -s.r + (j + 0.5) * cell, -10.0);
        sum += (1.0 - std::exp(-sphere_optical_depth(s, o, {0.0, 0.0, 1.0}, -kSphereLineIntegralInf, kSphereLineIntegralInf))) * cell * cell;
      }
    EXPECT_NEAR(sphere_opacity_area(s.r, k), sum, 2e-3 * sum) << k;
  }
  const double r = 0.8;
  EXPECT_NEAR(sphere_opacity_area(r, 1e-6), 1e-6 * 4.0 * kPi * r * r * r * (1.0 / 3.0 - kPi / 16.0), 1e-9);
  EXPECT_NEAR(sphere_opacity_area(r, 1e6), kPi * r * r, 1e-3 * kPi * r * r);
  EXPECT_EQ(sphere_opacity_area(r, 0.0), 0.0);
}

TEST(ShadowCaster, ASphereReachesItsRadiusAndAGaussianItsCube) {
  const ShadowCaster sphere(ConeSphere{{0.0, 0.0, 0.0}, 2.0, 1.0});
  const ShadowCaster gaussian(clamped_gaussian({0.0, 0.0, 0.0}, 3.0, 0.5));
  EXPECT_EQ(caster_reach(sphere), 2.0);
  EXPECT_NEAR(caster_reach(gaussian), 3.0 * std::sqrt(3.0), 1e-12);
  // The profile's increments are the optical depth over any interval inside the span.
  const glm::dvec3 o(0.4, 0.3, -5.0), w(0.0, 0.0, 1.0);
  for (const ShadowCaster& c : {sphere, gaussian}) {
    double a, b;
    ASSERT_TRUE(caster_span(c, o, w, a, b));
    const CasterRayProfile p = caster_ray_profile(c, o, w);
    const double m = 0.5 * (a + b);
    EXPECT_NEAR(p.cumulative(m) - p.cumulative(a), caster_optical_depth(c, o, w, a, m), 1e-9);
    EXPECT_NEAR(p.cumulative(b) - p.cumulative(a), caster_optical_depth(c, o, w, -kSphereLineIntegralInf, kSphereLineIntegralInf), 1e-9);
  }
}

}  // namespace
}  // namespace pyro
