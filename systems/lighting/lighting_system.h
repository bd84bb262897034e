#pragma once
// The lighting phase (ecs::Phase::light): gathers the light entities (DirectionalLight,
// AmbientLight) into the SceneLighting resource that the render systems read. It runs once per
// frame, before the camera phase, so a stereo pair is lit once for both eyes.
#include <vector>

#include "components/ambient_light.h"
#include "components/directional_light.h"
#include "components/scene_lighting.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"

namespace pyro {

// What the renderers use of lights given in order: the first directional light is the sun (its
// colour scaled by its intensity), and the ambient colours add up (the first copied, so that one
// light passes through unchanged). Without directional lights the sun is black; without ambient
// ones, so is the ambient term. The importer lights a scene's VDB volumes with the same.
SceneLighting combine_lights(const std::vector<DirectionalLight>& directional,
                             const std::vector<AmbientLight>& ambient);

// combine_lights over the world's light entities in entity-index order.
SceneLighting gather_lighting(ecs::World& world);

ecs::SystemDesc lighting_system();

}  // namespace pyro
