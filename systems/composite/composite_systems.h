#pragma once
// Composite phase, the `composite` system: each view's particle layer composited over its scene
// and the views composed into the output image for the stereo mode, in one full-screen pass.
// Reads the optional MediaComposition resource (how explosion layers are upsampled); its setup
// makes the Compositor resource.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc composite_system();

}  // namespace pyro
