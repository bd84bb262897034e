// Stability: densities tending to 0 and to their largest value (a splat opaque at its centre,
// rho -> 1, i.e. optical depth -> infinity), through the engine's own code: the CPU ground truth
// (systems/runtime/reference/particle_reference.h: tau0 = -ln(1 - rho), opacity 1 - exp(-dtau)) and the
// footprint table the GL splats multiply density by (engine/math/footprint.h).
// The ground truth evaluates them as -log1p(-rho) (rho clamped below 1) and -expm1(-dtau): finite,
// monotone, and accurate as rho -> 0. Written as -log(1 - rho) and 1 - exp(-tau), they would lose
// every digit below rho = 1e-16 (the optical depth and the pixel become 0) and give an infinite
// optical depth at rho = 1, whose colour weighting (dtau / sum of dtau) is then inf / inf = NaN;
// the tests below fail on either.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/math/camera_math.h"
#include "engine/math/footprint.h"
#include "systems/runtime/reference/particle_reference.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {
namespace {

// Optical depth along the axis through the particle's centre (the whole kernel).
double centre_depth(double rho) {
  return particle_optical_depth({0, 0, 0}, 1.0, rho, {0, 0, -10}, {0, 0, 1}, 0.0, 20.0);
}

struct Splat {
  glm::vec3 position;
  float density;
  glm::vec3 color;
};

// The ground truth of one or two particles of radius 1 on the view axis, 9 x 9 pixels: the ray of
// pixel (4, 4) passes through the centres.
RgbImage centre_view(const Splat& a, const std::optional<Splat>& b, const glm::dvec3& background) {
  ParticlePool pool(2);
  for (const std::optional<Splat>& s : {std::optional<Splat>(a), b}) {
    if (!s) continue;
    ParticleInit p;
    p.position = s->position;
    p.radius = 1.0f;
    p.density = s->density;
    p.color = s->color;
    pool.spawn(p);
  }
  const CameraFrame cam = make_camera_frame({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0f, 0.1f, 100.0f, 9, 9);
  return render_particles_reference(pool, cam, background, 1);
}

TEST(StabilityDensity, TinyDensitiesKeepTheirOpticalDepthAndOpacity) {
  for (double rho : {1e-6, 1e-12, 1e-17, 1e-25, 1e-38}) {
    // -ln(1 - rho) = rho + rho^2 / 2 + rho^3 / 3 + ... (the series, an independent form)
    const double series = rho + rho * rho / 2.0 + rho * rho * rho / 3.0;
    EXPECT_NEAR(centre_depth(rho) / series, 1.0, 1e-12) << rho;
  }
  // The image: one particle of colour 1 over black, seen through its centre, has opacity rho
  // there (the ground truth matches the splat's centre opacity), however small rho is.
  for (float rho : {1e-6f, 1e-12f, 1e-17f, 1e-25f, 1e-30f}) {
    const RgbImage img = centre_view({{0, 0, 0}, rho, {1, 1, 1}}, {}, glm::dvec3(0.0));
    EXPECT_NEAR(img.at(4, 4)[0] / double(rho), 1.0, 1e-5) << rho;
  }
}

TEST(StabilityDensity, DensitiesTowardsOneStayFiniteAndMonotone) {
  double previous = 0.0;
  for (double rho : {0.5, 0.9, 0.999, 1.0 - 1e-9, 1.0 - 1e-15, 1.0}) {
    const double tau = centre_depth(rho);
    EXPECT_TRUE(std::isfinite(tau)) << rho;
    EXPECT_GE(tau, previous) << rho;
    previous = tau;
  }
  // One opaque particle over a grey background: its centre shows its own colour alone.
  const RgbImage one = centre_view({{0, 0, 0}, 1.0f, {1, 0, 0}}, {}, glm::dvec3(0.2));
  EXPECT_NEAR(one.at(4, 4)[0], 1.0f, 1e-6f);
  EXPECT_NEAR(one.at(4, 4)[1], 0.0f, 1e-6f);
  // Two opaque particles of different colours over each other, seen through their centres: every
  // pixel is finite and in [0, 1], and the front particle hides the back one.
  const RgbImage two = centre_view({{0, 0, 0}, 1.0f, {1, 0, 0}}, Splat{{0, 0, -0.5f}, 1.0f, {0, 0, 1}},
                                   glm::dvec3(0.2));
  for (float v : two.rgb) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
  EXPECT_GT(two.at(4, 4)[0], 0.99f);
}

TEST(StabilityDensity, SplatOpacityNeverExceedsTheDensity) {
  // The GL splat's opacity is density x footprint (content/shaders/billboard.frag): with the
  // table scaled to a largest entry of exactly 1, a splat of density 1 is opaque at most, never
  // above, and every texel is finite.
  const FootprintDescription defaults;
  for (int size : {2, defaults.size, 65}) {
    const FootprintTable t = make_footprint_table(size, defaults.intervals);
    float largest = 0.0f;
    for (float v : t.scaled) {
      ASSERT_TRUE(std::isfinite(v)) << size;
      ASSERT_GT(v, 0.0f) << size;
      largest = std::max(largest, v);
    }
    EXPECT_EQ(largest, 1.0f) << size;
  }
}

}  // namespace
}  // namespace pyro
