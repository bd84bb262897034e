#pragma once
// Composite phase: particle layers upsampled over each view's scene, then the views composed
// into the output image for the stereo mode.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc layer_composite_system();
ecs::SystemDesc stereo_compose_system();

}  // namespace pyro
