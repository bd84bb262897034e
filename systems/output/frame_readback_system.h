#pragma once
// Output phase: reads the first view's finished linear frame back into the FrameImage
// resource (for tests and analyses; PNG output reads the composed sRGB image instead).
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc frame_readback_system();

}  // namespace pyro
