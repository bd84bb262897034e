#pragma once
// A scene with its run options merged in: what every later layer of the runtime reads instead
// of the description and the options apart. Plain data (resolve_scene.h makes it).
#include <optional>

#include "components/explosion_shading.h"
#include "components/frame_clock.h"
#include "components/render_settings.h"
#include "components/stereo_camera.h"
#include "systems/runtime/quality/quality_settings.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct ResolvedScene {
  // The description as it runs: a quality pick's layer scale, footprint size and frame rate
  // (frames_per_second * substeps) applied.
  SceneDescription scene;
  RenderSettings settings;
  ExplosionShading shading;
  StereoCamera stereo;
  FrameClock clock;  // dt = 1 / scene.frames_per_second
  // Simulation steps per output frame (a quality pick's time step): output frame f is the
  // runtime's frame f * substeps.
  int substeps = 1;
  std::optional<QualitySettings> quality;
  // What the budget check measures targets with (systems/runtime/scene/scene_budget.h).
  int views = 1;               // 1 mono, 2 stereo
  int output_width = 0;        // the widest target: 2 x width side by side
  int driver_max_texture = 0;  // GL_MAX_TEXTURE_SIZE of the context the scene runs in
};

}  // namespace pyro
