#pragma once
// One frame of a scene as linear RGB at width x height (mono), for tests that score the engine's
// image against a reference.
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro::test {

// A runtime of the scene at width x height (mono) whose frames are read back.
inline SceneRuntime readback_runtime(const SceneDescription& scene, int width, int height) {
  RuntimeOptions o;
  o.readback = true;
  o.width_override = width;
  o.height_override = height;
  return SceneRuntime(scene, o);
}

inline RgbImage rendered_frame(const SceneDescription& scene, int width, int height, int frame = 0) {
  SceneRuntime runtime = readback_runtime(scene, width, height);
  runtime.draw_frame(frame);
  return rgb_of(runtime.image());
}

}  // namespace pyro::test
