// Fire is a light (systems/lighting/fire_lights.h): a lone fire particle emits its black-body
// radiance times its opacity over its disc, one buried in opaque smoke emits nothing, and in
// the shipped explosion, lit, the clustered lights carry exactly the emitters' total intensity;
// unlit, there are none.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "components/fire_lights.h"
#include "components/particle_medium.h"
#include "components/shadow_settings.h"
#include "engine/core/content_path.h"
#include "engine/math/sphere_line_integral.h"
#include "systems/lighting/fire_lights.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

ParticleInit fire_particle(glm::vec3 at, float temperature) {
  ParticleInit f;
  f.position = at;
  f.radius = 0.8f;
  f.density = 1.5f;
  f.opacity = 0.9f;
  f.temperature = temperature;
  f.medium = static_cast<uint8_t>(ParticleMedium::fire);
  return f;
}

std::vector<ShadowCaster> casters_of(const ParticlePool& p) {
  std::vector<ShadowCaster> c;
  for (size_t i = 0; i < p.size(); ++i)
    c.push_back(ConeSphere{{p.px[i], p.py[i], p.pz[i]}, p.radius[i], double(p.density[i]) * p.opacity[i]});
  return c;
}

TEST(FireLights, ALoneParticleEmitsItsRadianceTimesItsOpacityArea) {
  const ExplosionShading shading;
  const BlackbodyTable table = blackbody_emission_table(shading.fire_t_min, shading.fire_t_max, shading.fire_emission, 128);
  ParticlePool pool(4);
  pool.spawn(fire_particle({1.0f, 2.0f, 3.0f}, 3000.0f));
  const std::vector<PointEmitter> e = fire_emitters({&pool}, shading, table, casters_of(pool));
  ASSERT_EQ(e.size(), 1u);
  const glm::dvec3 want = glm::dvec3(sample_blackbody_rgb(table, 3000.0)) * sphere_opacity_area(0.8, 1.5 * 0.9);
  EXPECT_LT(glm::length(e[0].intensity - want), 1e-6 * glm::length(want));
  EXPECT_EQ(e[0].position, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_NEAR(e[0].radius, 0.8, 1e-7);

  // Buried in a dense smoke sphere, its light does not get out.
  ParticleInit smoke = fire_particle({1.0f, 2.0f, 3.0f}, 600.0f);
  smoke.medium = static_cast<uint8_t>(ParticleMedium::smoke);
  smoke.radius = 3.0f;
  smoke.density = 8.0f;
  pool.spawn(smoke);
  const std::vector<PointEmitter> buried = fire_emitters({&pool}, shading, table, casters_of(pool));
  ASSERT_EQ(buried.size(), 1u);
  EXPECT_LT(glm::length(buried[0].intensity), 1e-9 * glm::length(want));
}

TEST(FireLights, TheShippedExplosionLitHasLightsThatCarryItsFire) {
  SceneDescription scene = load_scene(content_path("scenes/explosion.json"));
  RuntimeOptions o;
  o.readback = false;
  o.width_override = o.height_override = 64;
  SceneRuntime unlit(scene, o);
  unlit.step();
  EXPECT_TRUE(unlit.world().resource<FireLights>().lights.empty());
  scene.shadows = ShadowSettings{};
  SceneRuntime lit(scene, o);
  for (int f = 0; f < 5; ++f) lit.step();
  const FireLights& fire = lit.world().resource<FireLights>();
  ASSERT_EQ(fire.lights.size(), size_t(ShadowSettings{}.fire_lights));
  EXPECT_GT(fire.emitters.size(), 100u);
  glm::dvec3 lights(0.0), emitters(0.0);
  for (const PointEmitter& l : fire.lights) lights += l.intensity;
  for (const PointEmitter& e : fire.emitters) emitters += e.intensity;
  EXPECT_GT(emitters.x, 0.0);
  EXPECT_LT(glm::length(lights - emitters), 1e-9 * glm::length(emitters));
}

}  // namespace
}  // namespace pyro
