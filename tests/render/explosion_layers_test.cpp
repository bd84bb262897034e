// Explosion shading (Umenhoffer et al. 2006, section 3): one dust particle's centre pixel
// against eq. 1 in closed form (alpha a C with C = E P(mu) exp(-tau r) + ambient, P
// Cornette-Shanks from engine/math). The media layers' upsampling behind an opaque edge is
// tested in tests/systems/composite/depth_aware_upsampling_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "components/explosion_shading.h"
#include "components/frame_image.h"
#include "engine/math/phase_function.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/one_particle_scene.h"

namespace pyro {
namespace {

SceneDescription dust_scene(const glm::vec3& at, float radius, float tau) {
  // Cloud particles are dust (medium 0), opacity 1.
  SceneDescription s = test::one_particle_scene(at, radius, tau, 96, 96, 50.0f);
  s.clouds[0].color = CloudDescription{}.color;
  s.directional_lights.at(0).direction = {-0.6f, -0.8f, 0.0f};
  s.directional_lights.at(0).color = {1.0f, 1.0f, 1.0f};
  s.ambient_lights.at(0).color = {0.1f, 0.1f, 0.1f};
  s.render.particles = ParticleShape::spherical;
  s.render.shading = ParticleShading::explosion;
  return s;
}

TEST(ExplosionShading, DustCentrePixelFollowsEquationOne) {
  // The phase function's parameter g as the paper's (0) and either side: the shader's closed
  // form against engine/math's.
  for (float g : {0.0f, 0.6f, -0.5f}) {
    const float r = 0.6f, tau = 1.2f;
    const SceneDescription s = dust_scene({0, 0, -3}, r, tau);
    SceneRuntime run(s);
    ExplosionShading shading;
    for (MediumShading& m : shading.media) {
      m.detail_amplitude = 0.0f;
      m.g = g;
    }
    run.world().set_resource<ExplosionShading>(shading);
    run.step();
    const FrameImage& img = run.image();
    const int x = img.width / 2, y = img.height / 2;
    // The centre pixel's ray passes within half a pixel of the centre: d ~ 0, ds ~ 2r.
    const float alpha = 1.0f - std::exp(-tau * 2.0f * r);
    const glm::vec3 light = glm::normalize(s.directional_lights.at(0).direction);
    const double mu = glm::dot(light, glm::vec3(0, 0, 1));  // towards the eye: +z
    const double p = cornette_shanks(mu, g);
    // From the centre towards the light the chord is r.
    const double c = shading.light_irradiance * p * std::exp(-tau * r) + 0.1;
    const double expected = alpha * shading.media[0].albedo * c;
    const float* px = &img.rgba[4 * (static_cast<size_t>(y) * img.width + x)];
    EXPECT_NEAR(px[0], expected, 0.02 * expected) << g;
    EXPECT_NEAR(px[1], expected, 0.02 * expected) << g;
  }
}

}  // namespace
}  // namespace pyro
