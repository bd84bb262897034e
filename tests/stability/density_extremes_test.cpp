// Stability: densities tending to 0 and to their largest value (a splat opaque at its centre,
// rho -> 1, i.e. optical depth -> infinity) in the CPU ground truth
// (systems/reference/particle_reference.h: tau0 = -ln(1 - rho), opacity 1 - exp(-dtau)).
// The engine evaluates them as -log1p(-rho) (rho clamped below 1) and -expm1(-dtau): finite,
// monotone, and accurate as rho -> 0. The naive formulas -log(1 - rho) and 1 - exp(-tau) lose
// every digit below rho = 1e-16 (the optical depth becomes 0) and give an infinite optical depth
// at rho = 1, whose colour weighting (dtau / sum of dtau) is then inf / inf = NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/math/camera_math.h"
#include "systems/reference/particle_reference.h"

namespace pyro {
namespace {

// Optical depth along the axis through the particle's centre (the whole kernel).
double centre_depth(double rho) {
  return particle_optical_depth({0, 0, 0}, 1.0, rho, {0, 0, -10}, {0, 0, 1}, 0.0, 20.0);
}

TEST(StabilityDensity, TinyDensitiesKeepTheirOpticalDepthNaiveLogLosesIt) {
  for (double rho : {1e-6, 1e-12, 1e-17, 1e-25, 1e-38}) {
    // -ln(1 - rho) = rho + rho^2 / 2 + rho^3 / 3 + ... (the series, an independent form)
    const double series = rho + rho * rho / 2.0 + rho * rho * rho / 3.0;
    EXPECT_NEAR(centre_depth(rho) / series, 1.0, 1e-12) << rho;
  }
  // Naive: -log(1 - rho) rounds 1 - rho to 1 below rho = 2^-53.
  EXPECT_EQ(-std::log(1.0 - 1e-17), 0.0);
}

TEST(StabilityDensity, DensitiesTowardsOneStayFiniteAndMonotoneNaiveGivesNaN) {
  double previous = 0.0;
  for (double rho : {0.5, 0.9, 0.999, 1.0 - 1e-9, 1.0 - 1e-15, 1.0}) {
    const double tau = centre_depth(rho);
    EXPECT_TRUE(std::isfinite(tau)) << rho;
    EXPECT_GE(tau, previous) << rho;
    previous = tau;
  }
  // Two opaque particles of different colours over each other, seen through their centres.
  ParticlePool pool(2);
  ParticleInit a, b;
  a.radius = b.radius = 1.0f;
  a.density = b.density = 1.0f;
  a.color = {1.0f, 0.0f, 0.0f};
  b.position = {0.0f, 0.0f, -0.5f};
  b.color = {0.0f, 0.0f, 1.0f};
  pool.spawn(a);
  pool.spawn(b);
  const CameraFrame cam = make_camera_frame({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f, 0.1f, 100.0f, 9, 9);
  const RgbImage img = render_particles_reference(pool, cam, glm::dvec3(0.2), 1);
  for (float v : img.rgb) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
  EXPECT_GT(img.at(4, 4)[0], 0.99f);  // the front particle hides the back one
  // Naive: optical depth -log(1 - 1) = inf for each, opacity 1 - exp(-inf) = 1, colour
  // weighted by tau_i / sum tau: inf / inf.
  const double tau = -std::log(1.0 - 1.0);
  const double naive_red = (1.0 - std::exp(-(tau + tau))) * (tau * 1.0 + tau * 0.0) / (tau + tau);
  EXPECT_TRUE(std::isnan(naive_red));
}

}  // namespace
}  // namespace pyro
