#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

struct RenderBenchOptions {
  std::string scene;
  int width = 0, height = 0;  // 0: the scene's size
  int frames = 30;            // timed whole frames
  int pass_repeats = 15;      // timed particle passes per shading, interleaved
  ProgressSink* progress = nullptr;  // how far the run is (null: not reported)
};

// Times whole frames of a scene, then the particle pass alone with the kernel shader and with a
// trivial blending shader over the same instances, view and depth buffer (interleaved, medians),
// counting fragments with an occlusion query. efficiency = trivial time / kernel time.
nlohmann::json bench_render(const RenderBenchOptions& options);

}  // namespace pyro
