#pragma once
// The one linear readback of a drawn frame (systems/output/frame_source.h's LinearView): each
// rendered view's scene target, with its particle layer or media layers resolved into a linear
// float target by the compositor's own arithmetic. The frame_readback system and the output
// sinks read frames through it.
#include <vector>

#include "engine/ecs/access.h"
#include "engine/ecs/world.h"
#include "systems/output/frame_source.h"

namespace pyro {

// Makes the resources the readback uses (when the world has none yet). Main thread, GL current.
void make_linear_readback_resources(ecs::World& world);

// Adds what read_linear_views(world, with_depth) touches to a system's `access`.
void declare_linear_readback_access(ecs::Access& access, bool with_depth);

// Reads every view of `world`'s last drawn frame (GpuFrame); with `with_depth`, each view's
// depth too (window depths made view depths with the View resource's clip distances: engine/math/
// camera_math.h). Main thread, GL current.
std::vector<LinearView> read_linear_views(ecs::World& world, bool with_depth);

}  // namespace pyro
