#pragma once
#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

struct JohnsonBenchOptions {
  int frames = 90;          // frames along the scripted path, per scene
  int width = 1024, height = 768;
  float layer_scale = 0.25f;  // particle layer resolution (1: full), relative to the views
  float frame_scale = 0.5f;   // views rendered at this fraction of 1024x768, then upscaled
  int error_samples = 5;      // frames along the path where the layer's RMSE is measured
  bool sync_timing = false;   // per-system times include their GPU work (slower frames)
  ProgressSink* progress = nullptr;  // how far the run is (null: not reported)
};

// Johnson & McAllister 2005, section 4.1: the box filled with 1000 particles of radius 0.4,
// 2000 of 0.4 and 2000 of 0.32; the viewer moves through the volume; full-screen red-cyan
// anaglyph stereo at 1024x768. Prints per scene avg and min fps, and the RMSE (linear, per
// channel, of the anaglyph as shown) of the reduced layer and frame resolutions against the
// full-resolution image.
nlohmann::json bench_johnson(const JohnsonBenchOptions& options);

}  // namespace pyro
