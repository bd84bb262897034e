#pragma once
// The lighting phase (ecs::Phase::light): gathers the light entities (DirectionalLight,
// AmbientLight) into the SceneLighting resource, which the light block (light_block.h) packs
// for the renderers. It runs once per
// frame, before the camera phase, so a stereo pair is lit once for both eyes.
#include <vector>

#include "components/ambient_light.h"
#include "components/directional_light.h"
#include "components/scene_lighting.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"

namespace pyro {

// The lights given in order as the renderers use them: every directional light a sun (its colour
// scaled by its intensity; the first is the key light, which casts the shadows), and the ambient
// colours added up (the first copied, so that one light passes through unchanged). Without
// directional lights there is no sun; without ambient ones the ambient term is black. The
// importer lights a scene's VDB volumes with the same.
SceneLighting combine_lights(const std::vector<DirectionalLight>& directional,
                             const std::vector<AmbientLight>& ambient);

// combine_lights over the world's light entities in entity-index order.
SceneLighting gather_lighting(ecs::World& world);

ecs::SystemDesc lighting_system();

}  // namespace pyro
