#pragma once
// The light phase's last step: the scene's lights (SceneLighting) and the fire's point lights
// (FireLights) packed into the one block every renderer binds (components/light_block.h).
#include "components/fire_lights.h"
#include "components/light_block.h"
#include "components/scene_lighting.h"
#include "engine/ecs/schedule.h"

namespace pyro {

// The block of `lighting` and, when given, the fire's clustered lights (at most kMaxFireLights).
// Throws std::invalid_argument past kMaxSuns suns (the scene loader refuses such a scene first).
LightBlock pack_lights(const SceneLighting& lighting, const FireLights* fire);

// The block of the world's lights: its SceneLighting (the default sun without one) and FireLights.
LightBlock gather_light_block(ecs::World& world);

// Writes the LightBlock resource once a frame, after the lighting and fire-light systems (which
// the schedule must hold).
ecs::SystemDesc light_block_system();

}  // namespace pyro
