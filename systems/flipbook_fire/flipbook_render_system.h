#pragma once
// Flipbook fire (Rose 2007, sections 4.3-4.6), two systems:
//   flipbook_orient (sort phase, after the camera phase made View): every fire (components/
//     flipbook_fire.h) turns to face the mid-eye point (the mono camera, View::frame) and its
//     billboards show this frame's flame frames: the FlipbookDrawList resource, one for all eyes.
//   flipbook_render (render phase, after the opaque meshes): that one draw list is blended into
//     each rendered view's scene target, fires farthest first. Needs a FlipbookRenderer resource
//     holding the flipbooks (systems/flipbook_fire/flipbook_world.h makes it).
#include "engine/ecs/schedule.h"

namespace pyro {

ecs::SystemDesc flipbook_orient_system();
ecs::SystemDesc flipbook_render_system();

}  // namespace pyro
