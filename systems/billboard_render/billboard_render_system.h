#pragma once
// Render phase, second pass: blends the sorted particles over the opaque frame.
// Needs a BillboardRenderer resource (made from the scene's footprint table).
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc billboard_render_system();

}  // namespace pyro
