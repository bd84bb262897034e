#pragma once
// Output phase: reads the finished frame back into the FrameImage resource.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc frame_readback_system();

}  // namespace pyro
