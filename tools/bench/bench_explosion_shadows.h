#pragma once
// pyro bench explosion-shadows [SCENE]: the explosion's dust and smoke shadowed by the light phase
// (docs/lighting.md), each shadow setting timed and scored against the truth, in one run:
//  - the truth: full-resolution layers, every fragment's transmittance summed exactly over every
//    particle and its fire light over every fire particle (ShadowSettings::exact_fragments; no
//    particle culled, so none that shadows is missing);
//  - each setting: the scene's own layer scale, its frames per second, and that over the same
//    scene with shadows off (the media shadowed by themselves alone, as before lighting existed),
//    the two timed in alternating blocks so that the machine's drift falls on both;
//  - shadows off itself, scored against the same truth: what the light phase buys.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "components/shadow_settings.h"
#include "engine/core/progress_sink.h"

namespace pyro {

struct ExplosionShadowsBenchOptions {
  std::string scene = "content/scenes/explosion.json";
  int width = 512, height = 512;
  float layer_scale = 0.5f;  // the measured settings' layers (the truth's are full resolution)
  int frames = 60;           // timed frames of each setting
  int error_frames = 4;      // frames, spread over the timed ones, where RMSE is measured
  // The settings measured (method, map size and slices, fire lights); shadows off is always
  // measured first, as the baseline.
  std::vector<ShadowSettings> settings{
      {ShadowMethod::none, 64, 32, 4},       {ShadowMethod::shadow_map, 32, 16, 4},
      {ShadowMethod::shadow_map, 64, 32, 1}, {ShadowMethod::shadow_map, 64, 32, 4},
      {ShadowMethod::shadow_map, 64, 32, 8}, {ShadowMethod::shadow_map, 128, 64, 4},
      {ShadowMethod::rays, 64, 32, 4}};
  ProgressSink* progress = nullptr;
};

// Fields: scene, width, height, layer_scale, frames, error_frames, off {fps (the best of its
// timings), rmse_vs_truth}, settings [{method, map_size, map_slices, fire_lights, fps, off_fps
// (timed beside it), fps_over_off, rmse_vs_truth}].
// Throws UserError naming the scene when its particles are not the explosion's media.
nlohmann::json bench_explosion_shadows(const ExplosionShadowsBenchOptions& options);

}  // namespace pyro
