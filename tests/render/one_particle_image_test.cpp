// One particle rendered through the real GL pipeline (EGL, llvmpipe without a GPU), compared
// pixel by pixel against the closed-form footprint: alpha = rho * exp(-(x^2+y^2)/2) in kernel
// coordinates, where the billboard's edge is kernel coordinate 3.
#include <gtest/gtest.h>

#include <cmath>

#include "components/draw_list.h"
#include "components/frame_image.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/one_particle_scene.h"

namespace pyro {
namespace {

SceneDescription one_particle_scene(const glm::vec3& at, float radius, float density) {
  SceneDescription s = test::one_particle_scene(at, radius, density, 161, 121, 40.0f, 1e-4f);
  s.name = "one particle";
  return s;
}

void check_against_closed_form(const glm::vec3& at, float radius, float density) {
  SceneRuntime runtime(one_particle_scene(at, radius, density));
  runtime.step();
  const FrameImage& img = runtime.image();
  const glm::vec4 p = gathered_draw_list(runtime.world().resource<EyeDrawLists>(), 0).center_radius.at(0);
  // Viewplane-facing billboard at view depth -p.z: an affine map from pixels to the plane.
  const double depth = -p.z;
  const double focal = (img.height / 2.0) / std::tan(40.0 * M_PI / 360.0);  // pixels at depth 1
  const double cx = img.width / 2.0 + p.x / depth * focal;
  const double cy = img.height / 2.0 - p.y / depth * focal;
  const double pixels_per_unit = focal / depth;
  int inside = 0;
  double max_err = 0.0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const double kx = ((x + 0.5) - cx) / pixels_per_unit / radius * 3.0;
      const double ky = -((y + 0.5) - cy) / pixels_per_unit / radius * 3.0;
      const size_t k = (static_cast<size_t>(y) * img.width + x) * 4;
      // White particle over black: the colour is the particle's opacity (the frame's own alpha
      // is 1 everywhere, since the opaque pass clears it to 1).
      const double got = img.rgba[k];
      ASSERT_NEAR(img.rgba[k + 1], got, 1e-6);
      ASSERT_NEAR(img.rgba[k + 2], got, 1e-6);
      if (std::abs(kx) < 2.95 && std::abs(ky) < 2.95) {
        const double expected = density * std::exp(-(kx * kx + ky * ky) / 2.0);
        max_err = std::max(max_err, std::abs(got - expected));
        ++inside;
      } else if (std::abs(kx) > 3.05 || std::abs(ky) > 3.05) {
        ASSERT_EQ(got, 0.0) << "fragment outside the billboard at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(inside, 400);
  // Bilinear footprint (<= 2.1e-3 x rho) plus half-float storage (~5e-4 at these values).
  EXPECT_LE(max_err, 2.1e-3 * density + 1e-3) << "over " << inside << " pixels";
}

TEST(OneParticleImage, CentredParticleMatchesClosedForm) {
  check_against_closed_form({0.0f, 0.0f, -5.0f}, 0.8f, 0.8f);
}

TEST(OneParticleImage, OffCentreParticleMatchesClosedForm) {
  check_against_closed_form({0.9f, -0.4f, -6.0f}, 0.6f, 0.5f);
}

}  // namespace
}  // namespace pyro
