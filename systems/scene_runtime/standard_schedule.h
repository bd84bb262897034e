#pragma once
// The fourth layer of the runtime: the standard schedule of systems, by phase:
//   spawn:     emitter (clouds), particle_emitter (explosion emitters)
//   simulate:  animation (cloud drift), particle_animation (explosion particles), camera_orbit
//   sort:      sorting (one draw list per view)
//   camera:    camera (mono frame and eye frames), flipbook_orient
//   render:    mesh_render, flipbook_render, billboard_render (per view; particles into a layer
//              when reduced)
//   composite: composite (particle layers over the scene, views into the output image)
//   output:    readback (options.readback: every view, linear, for tests and measurements)
// With options.profile each render, composite and output system is a GPU pass of its own
// (engine/gpu/gpu_pass_timer.h); with options.sync_timing each system finishes its GPU work.
#include <vector>

#include "engine/ecs/schedule.h"
#include "systems/scene_runtime/runtime_options.h"

namespace pyro {

// The systems above, in insertion order, without the wrappers.
std::vector<ecs::SystemDesc> standard_systems(bool readback);

ecs::Schedule standard_schedule(const RuntimeOptions& options);

}  // namespace pyro
