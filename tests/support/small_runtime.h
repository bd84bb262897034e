#pragma once
// Runtime options for tests that step a scene on the GPU but look at its state, not its image:
// a 48x48 view and no readback, so that a run of frames stays cheap.
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro::test {

inline RuntimeOptions small_runtime() {
  RuntimeOptions o;
  o.readback = false;
  o.width_override = 48;
  o.height_override = 48;
  return o;
}

}  // namespace pyro::test
