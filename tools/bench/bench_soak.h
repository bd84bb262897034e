#pragma once
// Long runs: `pyro bench soak SCENE --frames N` simulates N frames (rendering every
// k-th, or none) and watches for NaN or infinity in the particle state, for growth in resident
// memory and for growth in time per frame. A benchmark, not a timed test.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"

namespace pyro {

struct SoakBenchOptions {
  std::string scene;
  long frames = 100000;
  int render_every = 0;   // 0: never render; k: render (and read back nothing) every k-th frame
  int width = 256, height = 256;  // when rendering
  // > 0: every this many seconds of scene time the emitters' bursts fire again (their burst
  // schedules are re-armed), so a one-shot explosion repeats through a long run instead of dying
  // out after its particles' lifetime. 0: the scene as written.
  double rearm_every = 0.0;
  ProgressSink* progress = nullptr;  // how far the run is (null: not reported)
};

// Fields: frames, seconds, non_finite (particle values that are NaN or infinite, summed over
// every frame checked), first_non_finite_frame (-1: none), rss_start_bytes and rss_end_bytes
// (/proc/self/statm after the first frame and after the last), rss_max_bytes,
// ms_per_frame_first_10pct and ms_per_frame_last_10pct, live particles then, and
// time_growth = last / first, spawned (over all emitters) and rearms.
nlohmann::json bench_soak(const SoakBenchOptions& options);

}  // namespace pyro
