#pragma once
// Composite phase: each view's particle layer composited over its scene and the views composed
// into the output image for the stereo mode, in one full-screen pass.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc stereo_compose_system();

}  // namespace pyro
