#include "systems/lighting/lighting_system.h"

#include <cstdint>

#include "components/ambient_light.h"
#include "components/directional_light.h"

namespace pyro {

SceneLighting gather_lighting(ecs::World& world) {
  SceneLighting lighting;
  lighting.directional_lights = 0;
  uint32_t first = UINT32_MAX;
  world.each<const DirectionalLight>([&](ecs::Entity e, const DirectionalLight& light) {
    ++lighting.directional_lights;
    if (e.index >= first) return;
    first = e.index;
    lighting.sun_direction = light.direction;
    lighting.sun_color = light.color * light.intensity;
  });
  if (lighting.directional_lights == 0) lighting.sun_color = glm::vec3(0.0f);
  bool any_ambient = false;
  world.each<const AmbientLight>([&](const AmbientLight& light) {
    lighting.ambient = any_ambient ? lighting.ambient + light.color : light.color;
    any_ambient = true;
  });
  if (!any_ambient) lighting.ambient = glm::vec3(0.0f);
  return lighting;
}

ecs::SystemDesc lighting_system() {
  return {.name = "lighting",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<DirectionalLight, AmbientLight>, ecs::Writes<SceneLighting>>(),
          .run = [](ecs::World& world) { world.resource<SceneLighting>() = gather_lighting(world); },
          .setup = [](ecs::World& world) {
            if (!world.has_resource<SceneLighting>()) world.set_resource<SceneLighting>();
          }};
}

}  // namespace pyro
