#pragma once
// Output phase, the `frame_readback` system: reads every view back, linear, with its particle
// layer composited (linear_readback.h), into the FrameImage resource, every frame (for tests and
// accuracy measurements; a run's output frames go to sinks instead: frame_output.h). Runs only
// when a runtime asks for readback: it costs a full-frame transfer.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc frame_readback_system();

}  // namespace pyro
