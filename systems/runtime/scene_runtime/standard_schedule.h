#pragma once
// The fourth layer of the runtime: the standard schedule of systems, by phase:
//   spawn:     cloud_emitter (clouds), emitter (explosion emitters)
//   simulate:  cloud_drift (cloud drift), animation (explosion particles), camera_orbit
//   camera:    stereo_camera (mono frame and eye frames, into View)
//   sort:      sorting (one draw list per view, for View's eyes), flipbook_orient
//   render:    mesh_render, flipbook_render, billboard_render (per view; particles into a layer
//              when reduced)
//   composite: composite (particle layers over the scene, views into the output image)
//   output:    frame_readback (options.readback: every view, linear, for tests and
//              measurements)
// With options.profile each GL system (SystemDesc::main_thread: the render, composite and output
// phases) is a GPU pass of its own (engine/gpu/gpu_pass_timer.h); with options.sync_timing each
// GL system finishes its GPU work. The systems' setup (Schedule::setup) runs once the world is
// built. options.extra_systems (an embedding program's own) follow the standard ones.
#include <vector>

#include "engine/ecs/schedule.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

// The systems above, in insertion order, without the wrappers.
std::vector<ecs::SystemDesc> standard_systems(bool readback);

ecs::Schedule standard_schedule(const RuntimeOptions& options);

}  // namespace pyro
