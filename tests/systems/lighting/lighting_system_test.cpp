// The lighting phase on hand-built worlds: every directional light is a sun in entity-index
// order (its colour times its intensity, its direction as given and toward it normalised), the
// first the key light; the ambient lights add up; a world without lights is dark.
#include "systems/lighting/lighting_system.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

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
  ASSERT_EQ(l.suns.size(), 2u);
  EXPECT_EQ(l.key(), &l.suns[0]);
  EXPECT_EQ(l.suns[0].travel, glm::vec3(0.0f, -2.0f, 0.0f)) << "as given, not normalised";
  EXPECT_EQ(l.suns[0].toward, glm::vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(l.suns[0].radiance, glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_EQ(l.suns[1].toward, glm::vec3(-1.0f, 0.0f, 0.0f));
  EXPECT_EQ(l.suns[1].radiance, glm::vec3(9.0f, 9.0f, 9.0f));
  EXPECT_EQ(l.ambient, glm::vec3(0.6f, 0.45f, 0.425f));
}

TEST(LightingSystem, OneLightPassesThroughUnchanged) {
  ecs::World world;
  const DirectionalLight sun{{-0.4f, -1.0f, -0.3f}, {0.9f, 0.8f, 0.7f}, 1.0f};
  const AmbientLight sky{{0.31f, 0.37f, 0.41f}};
  world.emplace<DirectionalLight>(world.create(), sun);
  world.emplace<AmbientLight>(world.create(), sky);
  const SceneLighting l = gather_lighting(world);
  ASSERT_EQ(l.suns.size(), 1u);
  EXPECT_EQ(l.suns[0].travel, sun.direction);
  EXPECT_EQ(l.suns[0].toward, -glm::normalize(sun.direction));
  EXPECT_EQ(l.suns[0].radiance, sun.color);
  EXPECT_EQ(l.ambient, sky.color);
}

TEST(LightingSystem, AWorldWithoutLightsIsDark) {
  ecs::World world;
  const SceneLighting l = gather_lighting(world);
  EXPECT_TRUE(l.suns.empty());
  EXPECT_EQ(l.key(), nullptr);
  EXPECT_EQ(l.key_radiance(), glm::vec3(0.0f));
  EXPECT_FALSE(l.key_shines());
  EXPECT_EQ(l.ambient, glm::vec3(0.0f));
}

}  // namespace
}  // namespace pyro
