#pragma once
// One frame of a scene as linear RGB at width x height (mono), for tests that score the engine's
// image against a reference.
#include "systems/runtime/reference/world_snapshot.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro::test {

inline RgbImage rendered_frame(const SceneDescription& scene, int width, int height, int frame = 0) {
  RuntimeOptions o;
  o.readback = true;
  o.width_override = width;
  o.height_override = height;
  SceneRuntime runtime(scene, o);
  runtime.draw_frame(frame);
  return rgb_of(runtime.image());
}

}  // namespace pyro::test
