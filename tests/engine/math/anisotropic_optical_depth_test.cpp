// The anisotropic Gaussian's closed-form optical depth (engine/math/anisotropic_optical_depth.h)
// against numerical quadrature of the extinction field built independently (Sigma = R S^2 R^T,
// inverted by glm), against the isotropic sphere's closed form, under rotations of the whole
// configuration, and at one hand-computed point that tells the rotation from its transpose.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "engine/core/rng.h"
#include "engine/math/anisotropic_optical_depth.h"
#include "tests/support/random_anisotropic.h"

namespace pyro {
namespace {

// Midpoint quadrature of sigma(o + t w) over [a, b], sigma from the covariance matrix (not from
// the whitening the closed form uses). The field jumps at the ellipsoid (from k e^-4.5 to 0), so
// the rule's error there is at most about h k e^-4.5 per crossing.
double quadrature_depth(const AnisotropicGaussian& g, const glm::dvec3& o, const glm::dvec3& w,
                        double a, double b, int n) {
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(g.rotation)));
  const glm::dvec3 s(g.scale);
  const glm::dmat3 s2(s.x * s.x, 0, 0, 0, s.y * s.y, 0, 0, 0, s.z * s.z);
  const glm::dmat3 inv = glm::inverse(r * s2 * glm::transpose(r));
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 d = o + (a + (i + 0.5) * h) * w - glm::dvec3(g.centre);
    const double m2 = glm::dot(d, inv * d);
    if (m2 <= 9.0) sum += g.extinction * std::exp(-0.5 * m2);
  }
  return sum * h;
}

glm::dvec3 random_unit(Rng& rng) {
  for (;;) {
    const glm::dvec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double l = glm::length(v);
    if (l > 0.1 && l <= 1.0) return v / l;
  }
}

TEST(AnisotropicOpticalDepth, MatchesQuadratureForRandomParticlesAndRays) {
  Rng rng(71);
  int hits = 0, inside = 0;
  for (int k = 0; k < 120; ++k) {
    const AnisotropicGaussian g = test::random_anisotropic(rng, 1.0f, 0.05f, 0.8f, 0.5f, 4.0f);
    // Aim near the centre so that most rays hit; start some rays inside (the ellipsoid's
    // smallest radius is 3 * 0.05) and some far outside.
    const glm::dvec3 w = random_unit(rng);
    const glm::dvec3 aim = glm::dvec3(g.centre) + 0.9 * random_unit(rng) * double(rng.uniform());
    const double back = k % 3 == 0 ? 0.05 : 6.0;
    const glm::dvec3 o = aim - back * w;
    const double a = k % 4 == 1 ? back : 0.0;  // some intervals start at the aim point
    const double b = a + rng.uniform(0.1f, 12.0f);
    const double got = anisotropic_optical_depth(g, o, w, a, b);
    const double want = quadrature_depth(g, o, w, a, b, 200000);
    const double tol = 1e-5 * double(g.extinction) + 1e-6 * want;
    EXPECT_NEAR(got, want, tol) << "particle " << k;
    hits += got > 0.0;
    const glm::dvec3 u = whitening_matrix(g) * (o - glm::dvec3(g.centre));
    inside += glm::dot(u, u) < 9.0;
  }
  // The sample covers what it claims to: rays that hit, miss, and start inside.
  EXPECT_GT(hits, 60);
  EXPECT_LT(hits, 120);
  EXPECT_GT(inside, 10);
}

TEST(AnisotropicOpticalDepth, EmptyIntervalsAndMissingRaysGiveZero) {
  AnisotropicGaussian g;
  g.scale = {0.5f, 1.0f, 2.0f};
  g.extinction = 3.0f;
  const glm::dvec3 o(0.0, 0.0, -10.0), w(0.0, 0.0, 1.0);
  EXPECT_GT(anisotropic_optical_depth(g, o, w, 0.0, 20.0), 0.0);
  EXPECT_EQ(anisotropic_optical_depth(g, o, w, 10.0, 10.0), 0.0);   // a = b
  EXPECT_EQ(anisotropic_optical_depth(g, o, w, 12.0, 8.0), 0.0);    // a > b
  EXPECT_EQ(anisotropic_optical_depth(g, o, w, 0.0, 3.9), 0.0);     // ends before z = -6
  // x = 1.6 > 3 * 0.5: outside the ellipsoid's silhouette.
  EXPECT_EQ(anisotropic_optical_depth(g, {1.6, 0.0, -10.0}, w, 0.0, 20.0), 0.0);
  g.extinction = 0.0f;
  EXPECT_EQ(anisotropic_optical_depth(g, o, w, 0.0, 20.0), 0.0);
}

TEST(AnisotropicOpticalDepth, IsotropicCaseIsTheTruncatedSphereClosedForm) {
  // scale (s, s, s): along a line at miss distance d the chord is |z| <= sqrt(9 s^2 - d^2) and
  //   tau = k exp(-d^2 / (2 s^2)) s sqrt(2 pi) erf(sqrt(9 s^2 - d^2) / (s sqrt 2)).
  Rng rng(5);
  for (int k = 0; k < 20; ++k) {
    AnisotropicGaussian g;
    const double s = double(float(0.3 + k * 0.05));  // as stored
    g.scale = glm::vec3(float(s));
    g.rotation = test::random_rotation(rng);  // any rotation of a sphere is the sphere
    g.extinction = 2.0f;
    const double d = 0.14 * k * s;  // up to 2.66 s
    const double z = std::sqrt(9.0 * s * s - d * d);
    const double want = 2.0 * std::exp(-d * d / (2.0 * s * s)) * s * std::sqrt(2.0 * std::numbers::pi) *
                        std::erf(z / (s * std::numbers::sqrt2));
    const glm::dvec3 w = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    const glm::dvec3 side = glm::normalize(glm::cross(w, glm::dvec3(1.0, 0.0, 0.0)));
    EXPECT_NEAR(anisotropic_optical_depth(g, d * side - 10.0 * w, w, 0.0, 100.0), want, 1e-12 * want + 1e-15);
  }
}

TEST(AnisotropicOpticalDepth, RotatingTheWholeSceneChangesNothing) {
  Rng rng(9);
  for (int k = 0; k < 50; ++k) {
    AnisotropicGaussian g = test::random_anisotropic(rng, 1.0f, 0.1f, 0.7f, 1.0f, 3.0f);
    const glm::dvec3 w = random_unit(rng);
    const glm::dvec3 o = glm::dvec3(g.centre) + 0.3 * random_unit(rng) - 4.0 * w;
    const double before = anisotropic_optical_depth(g, o, w, 0.5, 7.0);
    const glm::dquat q(glm::normalize(glm::dquat(test::random_rotation(rng))));
    AnisotropicGaussian h = g;
    h.centre = glm::vec3(q * glm::dvec3(g.centre));
    h.rotation = glm::quat(q * glm::dquat(g.rotation));
    const double after = anisotropic_optical_depth(h, q * o, q * w, 0.5, 7.0);
    // Float storage of the rotated centre and rotation: relative 1e-6 is the float's share.
    EXPECT_NEAR(after, before, 2e-5 * (before + 1e-3)) << "particle " << k;
  }
}

TEST(AnisotropicOpticalDepth, RotationTurnsTheLocalAxesIntoTheWorld) {
  // Rotation by +30 degrees about z: the long local x axis points along (cos 30, sin 30, 0). A
  // ray parallel to world z through x0 * (cos 30, sin 30, 0) runs, in local coordinates, along
  // (x0, 0, z): tau = k exp(-x0^2 / (2 sx^2)) sz sqrt(2 pi) erf(sqrt((9 - x0^2 / sx^2) / 2)).
  // The transposed rotation (-30 degrees) would put that point at local y = -x0 sin 60 / sy
  // standard deviations, outside the ellipsoid (tau = 0).
  AnisotropicGaussian g;
  const double half = std::numbers::pi / 12.0;
  g.rotation = glm::quat(float(std::cos(half)), 0.0f, 0.0f, float(std::sin(half)));
  g.scale = {1.0f, 0.2f, 0.5f};
  g.extinction = 1.5f;
  const double x0 = 1.2, sx = 1.0, sz = 0.5, c30 = std::cos(2.0 * half), s30 = std::sin(2.0 * half);
  const double want = 1.5 * std::exp(-x0 * x0 / (2 * sx * sx)) * sz * std::sqrt(2.0 * std::numbers::pi) *
                      std::erf(std::sqrt((9.0 - x0 * x0 / (sx * sx)) / 2.0));
  const double got = anisotropic_optical_depth(g, {x0 * c30, x0 * s30, -5.0}, {0, 0, 1}, 0.0, 10.0);
  EXPECT_NEAR(got, want, 1e-6 * want);
  EXPECT_GT(want, 0.5);
}

TEST(AnisotropicOpticalDepth, ErfApproximationIsWithinItsStatedBound) {
  double worst = 0.0;
  for (int i = -60000; i <= 60000; ++i) {
    const double x = i * 1e-4;
    worst = std::max(worst, std::abs(erf_as_7_1_26(x) - std::erf(x)));
  }
  EXPECT_LE(worst, kErfAs7126MaxError);
  EXPECT_GT(worst, 1e-8);  // an approximation, not std::erf
}

}  // namespace
}  // namespace pyro
