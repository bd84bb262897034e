#pragma once
// Render phase, after the opaque meshes: every flipbook fire (components/flipbook_fire.h) faces
// the mid-eye point (the mono camera, View::frame) once per frame, and that one set of
// billboards is blended into each rendered view's scene target (Rose 2007, sections 4.3-4.6).
// Fires are drawn farthest first. Needs a FlipbookRenderer resource holding the flipbooks.
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc flipbook_render_system();

}  // namespace pyro
