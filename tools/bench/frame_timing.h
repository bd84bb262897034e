#pragma once
// The median wall time of a scene's frames (GPU work finished every frame), without readback:
// `pyro analyze billboard-modes` and `pyro chart billboard-modes` time their modes with it.
#include "systems/runtime/scene/scene_description.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

// One untimed warm-up frame (shaders, tables, targets), then `frames` timed frames; returns the
// median milliseconds per frame. options.readback is turned off.
double median_ms_per_frame(const SceneDescription& scene, RuntimeOptions options, int frames);

}  // namespace pyro
