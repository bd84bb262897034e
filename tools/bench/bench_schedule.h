#pragma once
// The parallel schedule against the sequential one in the same run (`pyro bench schedule`): two
// runtimes of the scene (opened as every command opens it, with one quality pick), one with T
// threads (0: one per core) and one with 1, stepped in turn (ABAB..., so that both see the same
// machine noise), the GPU finished after every frame. Reports the median ms per whole frame and
// per frame of the CPU phases (spawn to sort: the systems that may run concurrently; the GL phases
// run on the calling thread either way), their ratios, and whether the two produced the same
// output bytes.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/progress_sink.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct ScheduleBenchArgs {
  std::string scene;
  int frames = 60;
  int threads = 0;
  int width = 0, height = 0;
};

// {"scene", "frames", "threads", "ms_per_frame_parallel", "ms_per_frame_sequential",
// "frame_ratio", "speedup", "cpu_phases_ms_parallel", "cpu_phases_ms_sequential",
// "cpu_phases_ratio", "results_agree"}; the runtime's notes of the first opening go to `note`.
nlohmann::json bench_schedule(const ScheduleBenchArgs& a, const NoteSink& note,
                              ProgressSink* progress);

}  // namespace pyro
