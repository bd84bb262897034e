#include "systems/lighting/light_block.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pyro {

LightBlock pack_lights(const SceneLighting& lighting, const FireLights* fire) {
  if (lighting.suns.size() > size_t(kMaxSuns))
    throw std::invalid_argument("the light block holds at most " + std::to_string(kMaxSuns) +
                                " directional lights, given " + std::to_string(lighting.suns.size()));
  LightBlock block;
  block.ambient = glm::vec4(lighting.ambient, 0.0f);
  block.counts.x = int(lighting.suns.size());
  for (size_t i = 0; i < lighting.suns.size(); ++i) {
    block.sun_toward[i] = glm::vec4(lighting.suns[i].toward, 0.0f);
    block.sun_travel[i] = glm::vec4(lighting.suns[i].travel, 0.0f);
    block.sun_radiance[i] = glm::vec4(lighting.suns[i].radiance, 0.0f);
  }
  const size_t fires = fire ? std::min(fire->lights.size(), size_t(kMaxFireLights)) : 0;
  block.counts.y = int(fires);
  for (size_t j = 0; j < fires; ++j) {
    const PointEmitter& l = fire->lights[j];
    block.fire_position[j] = glm::vec4(float(l.position.x), float(l.position.y), float(l.position.z), float(l.radius));
    block.fire_intensity[j] = glm::vec4(float(l.intensity.x), float(l.intensity.y), float(l.intensity.z), 0.0f);
  }
  return block;
}

LightBlock gather_light_block(ecs::World& world) {
  const SceneLighting* lighting = world.try_resource<const SceneLighting>();
  return pack_lights(lighting ? *lighting : SceneLighting{}, world.try_resource<const FireLights>());
}

ecs::SystemDesc light_block_system() {
  return {.name = "light_block",
          .phase = ecs::Phase::light,
          .access = ecs::Access::of<ecs::Reads<SceneLighting, FireLights>, ecs::Writes<LightBlock>>(),
          .run = [](ecs::World& world) { world.resource<LightBlock>() = gather_light_block(world); },
          .setup = [](ecs::World& world) {
            if (!world.has_resource<LightBlock>()) world.set_resource<LightBlock>(gather_light_block(world));
          },
          .after = {"lighting", "fire_lights"}};
}

}  // namespace pyro
