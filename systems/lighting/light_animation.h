#pragma once
// Moving lights: each frame, every DirectionalLight with LightKeyframes is set to its keys at
// the frame's time (the simulate phase, so the light phase sees this frame's light).
#include "components/directional_light.h"
#include "components/light_keyframes.h"
#include "engine/ecs/schedule.h"

namespace pyro {

// The light at `time`: between two keys, colour and intensity interpolated linearly and the
// direction turned at a constant angular rate from one key's to the next (spherical linear
// interpolation of the unit directions; opposite directions turn about any perpendicular axis).
DirectionalLight light_at(const LightKeyframes& keys, double time);

ecs::SystemDesc light_animation_system();

}  // namespace pyro
