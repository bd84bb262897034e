#pragma once
// Output phase, the `frame_readback` system: reads every view back, linear, with its particle
// layer composited, into the FrameImage resource (for tests and accuracy measurements; PNG
// output reads the composed sRGB image instead). Runs only when a runtime asks for readback: it
// costs a full-frame transfer.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc frame_readback_system();

}  // namespace pyro
