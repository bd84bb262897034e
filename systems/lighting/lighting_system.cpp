#include "systems/lighting/lighting_system.h"

#include <algorithm>
#include <cstdint>
#include <utility>


namespace pyro {

SceneLighting combine_lights(const std::vector<DirectionalLight>& directional,
                             const std::vector<AmbientLight>& ambient) {
  SceneLighting lighting;
  lighting.suns.clear();
  for (const DirectionalLight& d : directional) lighting.suns.emplace_back(d.direction, d.color * d.intensity);
  if (ambient.empty()) lighting.ambient = glm::vec3(0.0f);
  for (size_t i = 0; i < ambient.size(); ++i)
    lighting.ambient = i == 0 ? ambient[i].color : lighting.ambient + ambient[i].color;
  return lighting;
}

namespace {

// A component type's values over the world's entities, in entity-index order.
template <typename T>
std::vector<T> in_index_order(ecs::World& world) {
  std::vector<std::pair<uint32_t, T>> found;
  world.each<const T>([&](ecs::Entity e, const T& value) { found.emplace_back(e.index, value); });
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<T> values;
  for (const auto& [index, value] : found) values.push_back(value);
  return values;
}

}  // namespace

SceneLighting gather_lighting(ecs::World& world) {
  return combine_lights(in_index_order<DirectionalLight>(world), in_index_order<AmbientLight>(world));
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
