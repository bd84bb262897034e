#pragma once
// The lighting phase (ecs::Phase::light): gathers the light entities (DirectionalLight,
// AmbientLight) into the SceneLighting resource that the render systems read. It runs once per
// frame, before the camera phase, so a stereo pair is lit once for both eyes.
#include "components/scene_lighting.h"
#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"

namespace pyro {

// The first directional light by entity index (its colour scaled by its intensity), how many
// there are, and the sum of the ambient lights (the first copied, so that one light passes
// through unchanged). Without directional lights the sun is black; without ambient ones, so is
// the ambient term.
SceneLighting gather_lighting(ecs::World& world);

ecs::SystemDesc lighting_system();

}  // namespace pyro
