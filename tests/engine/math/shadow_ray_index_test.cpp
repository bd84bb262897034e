// The shadow-ray index against the sum over every particle (the binning must lose none), and the
// line integral against its closed forms: through a particle's centre it is the optical depth
// -ln(1 - rho) that makes the splat's centre opacity rho; half of it from the centre outward.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/core/rng.h"
#include "engine/math/anisotropic_optical_depth.h"
#include "engine/math/gaussian_line_integral.h"
#include "engine/math/shadow_ray_index.h"

namespace pyro {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(GaussianLineIntegral, ThroughTheCentreItIsTheSplatsOpticalDepth) {
  const ClampedGaussian g = clamped_gaussian({1.0, 2.0, 3.0}, 0.6, 0.4);
  const glm::dvec3 w = glm::normalize(glm::dvec3(0.0, 1.0, 0.0));
  const double tau0 = -std::log(1.0 - 0.4);
  EXPECT_NEAR(gaussian_optical_depth(g, {1.0, -5.0, 3.0}, w, 0.0, kInf), tau0, 1e-12);
  // From the centre outward: half of it (the cube is symmetric about the centre).
  EXPECT_NEAR(gaussian_optical_depth(g, {1.0, 2.0, 3.0}, w, 0.0, kInf), 0.5 * tau0, 1e-12);
  // A ray missing the cube meets nothing.
  EXPECT_EQ(gaussian_optical_depth(g, {1.0 + 0.61, -5.0, 3.0}, w, 0.0, kInf), 0.0);
}

TEST(GaussianLineIntegral, TheTailFractionAndItsPolynomial) {
  // The closed form's ends and symmetry.
  EXPECT_DOUBLE_EQ(gaussian_tail_fraction(-3.0), 1.0);
  EXPECT_DOUBLE_EQ(gaussian_tail_fraction(3.0), 0.0);
  EXPECT_NEAR(gaussian_tail_fraction(0.0), 0.5, 1e-15);
  EXPECT_NEAR(gaussian_tail_fraction(0.7) + gaussian_tail_fraction(-0.7), 1.0, 1e-15);
  // Beyond x: the depth over [x s, 3 s] of a particle seen along an axis through its centre.
  const ClampedGaussian g = clamped_gaussian({0.0, 0.0, 0.0}, 0.9, 0.5);
  const double full = gaussian_optical_depth(g, {0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}, 0.0, kInf);
  EXPECT_NEAR(gaussian_optical_depth(g, {0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}, 5.0 + 0.4 * g.s, kInf),
              full * gaussian_tail_fraction(0.4), 1e-12);
  // The shaders' polynomial: within 1.2e-4 everywhere, clamped beyond +-3.
  const auto c = gaussian_tail_polynomial();
  double worst = 0.0;
  for (int i = 0; i <= 6000; ++i) {
    const double x = -3.0 + 6.0 * i / 6000.0;
    worst = std::max(worst, std::abs(evaluate_tail_polynomial(c, x) - gaussian_tail_fraction(x)));
  }
  EXPECT_LT(worst, 1.2e-4);
  EXPECT_GT(worst, 1e-6);  // a fit, not the function
  EXPECT_EQ(evaluate_tail_polynomial(c, 7.0), evaluate_tail_polynomial(c, 3.0));
}

// Gaussians, every fourth particle an explosion's sphere and every fourth from the second an
// anisotropic Gaussian of a fitted import, with each particle's optical depth from p toward the
// light by its own closed form.
struct RandomParticles {
  std::vector<ShadowCaster> casters;
  std::vector<AnisotropicGaussian> ellipsoids;  // of the casters i % 4 == 1, in their order

  double exact(size_t i, const glm::dvec3& p, const glm::dvec3& toward) const {
    const ShadowCaster& g = casters[i];
    if (i % 4 == 0) return sphere_optical_depth(g.sphere(), p, toward, 0.0, kInf);
    if (i % 4 == 1) return anisotropic_optical_depth(ellipsoids[i / 4], p, toward, 0.0, kInf);
    return gaussian_optical_depth(g.gaussian(), p, toward, 0.0, kInf);
  }
};

RandomParticles random_particles(Rng& rng, int n) {
  RandomParticles r;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 c(rng.uniform(-3.0f, 3.0f), rng.uniform(0.0f, 2.0f), rng.uniform(-3.0f, 3.0f));
    const float radius = rng.uniform(0.1f, 0.9f), density = rng.uniform(0.05f, 0.6f);
    if (i % 4 == 0) {
      r.casters.push_back(ConeSphere{c, radius, 3.0 * density});
    } else if (i % 4 == 1) {
      AnisotropicGaussian g;
      g.centre = glm::vec3(c);
      g.rotation = glm::normalize(glm::quat(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                                            rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)));
      g.scale = {rng.uniform(0.03f, 0.4f), rng.uniform(0.03f, 0.4f), rng.uniform(0.03f, 0.4f)};
      g.extinction = 4.0f * density;
      r.ellipsoids.push_back(g);
      r.casters.push_back(g);
    } else {
      r.casters.push_back(clamped_gaussian(c, radius, density));
    }
  }
  return r;
}

TEST(ShadowRayIndex, EqualsTheSumOverEveryParticle) {
  Rng rng(77);
  const RandomParticles particles = random_particles(rng, 400);
  for (const glm::dvec3 travel : {glm::dvec3(-0.5, -1.0, -0.35), glm::dvec3(0.0, -1.0, 0.0),
                                  glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.3, 0.2, -1.0)}) {
    const ShadowRayIndex index(particles.casters, travel);
    const glm::dvec3 toward = -glm::normalize(travel);
    double largest = 0.0, largest_ellipsoids = 0.0;
    for (int k = 0; k < 300; ++k) {
      const glm::dvec3 p(rng.uniform(-4.0f, 4.0f), rng.uniform(-1.0f, 3.0f), rng.uniform(-4.0f, 4.0f));
      double all = 0.0, ellipsoids = 0.0;
      for (size_t i = 0; i < particles.casters.size(); ++i) {
        const double tau = particles.exact(i, p, toward);
        all += tau;
        if (i % 4 == 1) ellipsoids += tau;
      }
      // The ellipsoid's whitening is kept in float: its depths agree to about 1e-7.
      EXPECT_NEAR(index.optical_depth_to_light(p), all, 1e-6 * (1.0 + all)) << k;
      largest = std::max(largest, all);
      largest_ellipsoids = std::max(largest_ellipsoids, ellipsoids);
    }
    EXPECT_GT(largest, 0.5);              // the points do lie in shadow
    EXPECT_GT(largest_ellipsoids, 0.05);  // some of it the ellipsoids'
  }
}

TEST(ShadowRayIndex, AnEmptyIndexCastsNoShadow) {
  const ShadowRayIndex index({}, {0.0, -1.0, 0.0});
  EXPECT_EQ(index.optical_depth_to_light({0.0, 0.0, 0.0}), 0.0);
}

}  // namespace
}  // namespace pyro
