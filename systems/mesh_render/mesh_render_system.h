#pragma once
// Render phase, first pass: clears the frame and draws opaque meshes with depth.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc mesh_render_system();

}  // namespace pyro
