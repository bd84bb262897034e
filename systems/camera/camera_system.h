#pragma once
// Camera phase: turns the first Camera entity (and its StereoCamera, if any) into this
// frame's View: the mono frame and the frames of the eyes that are rendered.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc camera_system();

}  // namespace pyro
