// The anisotropic CPU reference (systems/runtime/reference/anisotropic_reference.h): one particle's image
// is 1 - exp(-tau) of its closed-form optical depth at every pixel (so the per-particle pixel
// spans cut nothing), the centre pixel matches the hand-derived depth through the centre, and the
// image does not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "engine/core/rng.h"
#include "engine/math/anisotropic_optical_depth.h"
#include "systems/runtime/reference/anisotropic_reference.h"
#include "systems/runtime/reference/pixel_ray.h"
#include "tests/support/random_anisotropic.h"

namespace pyro {
namespace {

AnisotropicGaussian elongated() {
  AnisotropicGaussian g;
  g.centre = {0.2f, -0.1f, 0.0f};
  g.rotation = glm::angleAxis(0.6f, glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f)));
  g.scale = {0.9f, 0.12f, 0.3f};
  g.extinction = 2.5f;
  g.color = {1.0f, 0.6f, 0.3f};
  return g;
}

TEST(AnisotropicReference, OneParticleIsItsClosedFormAtEveryPixel) {
  const AnisotropicGaussian g = elongated();
  const CameraFrame cam = make_camera_frame({0.5f, 0.4f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                            45.0f, 0.1f, 100.0f, 48, 40);
  const glm::dvec3 bg(0.2, 0.3, 0.4);
  const RgbImage img = render_anisotropic_reference({g}, cam, bg, 1);
  int covered = 0;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const glm::dvec3 w = pixel_ray_direction(cam, x + 0.5, y + 0.5);
      const double tau = anisotropic_optical_depth(g, glm::dvec3(cam.eye), w, 0.0, 1e9);
      const double t = std::exp(-tau);
      covered += tau > 0.0;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(img.at(x, y)[c], g.color[c] * (1.0 - t) + bg[c] * t, 2e-6) << x << "," << y;
    }
  EXPECT_GT(covered, 100);
}

TEST(AnisotropicReference, CentrePixelShowsTheDepthThroughTheCentre) {
  // Through the centre m2_min = 0 and the chord is the whole ellipsoid:
  //   tau = k sqrt(2 pi / A) erf(3 / sqrt 2),  A = w^T Sigma^-1 w = |M w|^2.
  AnisotropicGaussian g = elongated();
  g.centre = {0.0f, 0.0f, 0.0f};
  const CameraFrame cam = make_camera_frame({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                            30.0f, 0.1f, 100.0f, 9, 9);
  const glm::dvec3 w(0.0, 0.0, -1.0);
  const glm::dvec3 mw = whitening_matrix(g) * w;
  const double tau = g.extinction * std::sqrt(2.0 * std::numbers::pi / glm::dot(mw, mw)) *
                     std::erf(3.0 / std::numbers::sqrt2);
  const RgbImage img = render_anisotropic_reference({g}, cam, glm::dvec3(0.0), 1);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(4, 4)[c], g.color[c] * -std::expm1(-tau), 1e-6);
}

TEST(AnisotropicReference, ImageDoesNotDependOnTheThreadCount) {
  Rng rng(3);
  std::vector<AnisotropicGaussian> ps;
  for (int i = 0; i < 30; ++i) ps.push_back(test::random_anisotropic(rng, 1.0f, 0.1f, 0.5f, 0.5f, 3.0f));
  const CameraFrame cam = make_camera_frame({0.0f, 0.5f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                                            45.0f, 0.1f, 100.0f, 32, 24);
  const RgbImage one = render_anisotropic_reference(ps, cam, glm::dvec3(0.1), 1);
  const RgbImage three = render_anisotropic_reference(ps, cam, glm::dvec3(0.1), 3);
  EXPECT_EQ(one.rgb, three.rgb);
}

}  // namespace
}  // namespace pyro
