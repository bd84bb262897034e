#pragma once
// Render phase, first pass, the `mesh_render` system: clears the frame and draws opaque meshes
// with depth. Its setup makes the MeshRenderer resource.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc mesh_render_system();

}  // namespace pyro
