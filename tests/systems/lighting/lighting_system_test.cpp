// The lighting phase on hand-built worlds: the first directional light by entity index is the
// sun (its colour times its intensity, its direction as given), the ambient lights add up, and
// a world without lights is dark.
#include "systems/lighting/lighting_system.h"

#include <gtest/gtest.h>

#include "components/ambient_light.h"
#include "components/directional_light.h"

namespace pyro {
namespace {

TEST(LightingSystem, TheFirstDirectionalLightIsTheSunAndAmbientLightsAdd) {
  ecs::World world;
  world.emplace<AmbientLight>(world.create(), AmbientLight{{0.1f, 0.2f, 0.3f}});
  world.emplace<DirectionalLight>(world.create(), DirectionalLight{{0.0f, -2.0f, 0.0f}, {1.0f, 0.5f, 0.25f}, 2.0f});
  world.emplace<DirectionalLight>(world.create(), DirectionalLight{{1.0f, 0.0f, 0.0f}, {9.0f, 9.0f, 9.0f}, 1.0f});
  world.emplace<AmbientLight>(world.create(), AmbientLight{{0.5f, 0.25f, 0.125f}});
  const ecs::SystemDesc system = lighting_system();
  system.setup(world);
  ecs::run_system_once(system, world);
  const SceneLighting& l = world.resource<SceneLighting>();
  EXPECT_EQ(l.directional_lights, 2);
  EXPECT_EQ(l.sun_direction, glm::vec3(0.0f, -2.0f, 0.0f)) << "as given, not normalised";
  EXPECT_EQ(l.sun_color, glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_EQ(l.ambient, glm::vec3(0.6f, 0.45f, 0.425f));
}

TEST(LightingSystem, OneLightPassesThroughUnchanged) {
  ecs::World world;
  const DirectionalLight sun{{-0.4f, -1.0f, -0.3f}, {0.9f, 0.8f, 0.7f}, 1.0f};
  const AmbientLight sky{{0.31f, 0.37f, 0.41f}};
  world.emplace<DirectionalLight>(world.create(), sun);
  world.emplace<AmbientLight>(world.create(), sky);
  const SceneLighting l = gather_lighting(world);
  EXPECT_EQ(l.sun_direction, sun.direction);
  EXPECT_EQ(l.sun_color, sun.color);
  EXPECT_EQ(l.ambient, sky.color);
}

TEST(LightingSystem, AWorldWithoutLightsIsDark) {
  ecs::World world;
  const SceneLighting l = gather_lighting(world);
  EXPECT_EQ(l.directional_lights, 0);
  EXPECT_EQ(l.sun_color, glm::vec3(0.0f));
  EXPECT_EQ(l.ambient, glm::vec3(0.0f));
}

}  // namespace
}  // namespace pyro
