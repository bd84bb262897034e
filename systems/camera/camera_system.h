#pragma once
// Camera phase: turns the first Camera entity into this frame's View (matrices and axes).
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc camera_system();

}  // namespace pyro
