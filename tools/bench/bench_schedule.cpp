#include "tools/bench/bench_schedule.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {

namespace {

double upper_middle(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Wall time of the last frame's CPU phases (spawn to sort): first start to last end.
double cpu_phases_ms(const ecs::Schedule& schedule) {
  using clock = std::chrono::steady_clock;
  clock::time_point first = clock::time_point::max(), last = clock::time_point::min();
  for (const ecs::SystemStats& s : schedule.stats()) {
    if (s.phase > ecs::Phase::sort) continue;
    first = std::min(first, s.last_start);
    const auto end = s.last_start + std::chrono::duration_cast<clock::duration>(
                                        std::chrono::duration<double, std::milli>(s.last_ms));
    last = std::max(last, end);
  }
  return first < last ? std::chrono::duration<double, std::milli>(last - first).count() : 0.0;
}

struct Timings {
  std::vector<double> frame_ms, cpu_ms;
};

void timed_step(SceneRuntime& runtime, Timings& t) {
  const auto t0 = std::chrono::steady_clock::now();
  runtime.step();
  glFinish();
  t.frame_ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  t.cpu_ms.push_back(cpu_phases_ms(runtime.schedule()));
}

}  // namespace

nlohmann::json bench_schedule(const ScheduleBenchArgs& a, const NoteSink& note,
                              ProgressSink* progress_sink) {
  // Both runtimes open the scene as every command does, with one quality pick.
  OpenSceneOptions open;
  open.runtime.readback = false;
  open.runtime.width_override = a.width;
  open.runtime.height_override = a.height;
  open.runtime.threads = a.threads;
  open.on_note = note;
  const OpenedScene opened_parallel = open_scene(a.scene, open);
  open.description = opened_parallel.description;
  open.quality = opened_parallel.quality;
  open.on_note = {};
  open.runtime.threads = 1;
  const OpenedScene opened_sequential = open_scene(a.scene, open);
  SceneRuntime& parallel = *opened_parallel.runtime;
  SceneRuntime& sequential = *opened_sequential.runtime;
  parallel.step(), sequential.step();  // warm-up: shaders, tables, targets, worker threads
  Timings par, seq;
  ProgressTask progress(progress_sink, "bench schedule", size_t(a.frames));
  for (int f = 0; f < a.frames; ++f) {
    timed_step(parallel, par);
    timed_step(sequential, seq);
    progress.update(size_t(f) + 1);
  }
  progress.finish();
  const double par_ms = upper_middle(par.frame_ms), seq_ms = upper_middle(seq.frame_ms);
  const double par_cpu = upper_middle(par.cpu_ms), seq_cpu = upper_middle(seq.cpu_ms);
  return {{"scene", a.scene},
          {"frames", a.frames},
          {"threads", parallel.schedule().effective_threads()},
          {"ms_per_frame_parallel", par_ms},
          {"ms_per_frame_sequential", seq_ms},
          {"frame_ratio", par_ms / seq_ms},
          {"speedup", seq_ms / par_ms},
          {"cpu_phases_ms_parallel", par_cpu},
          {"cpu_phases_ms_sequential", seq_cpu},
          {"cpu_phases_ratio", seq_cpu > 0 ? par_cpu / seq_cpu : 1.0},
          {"results_agree", parallel.read_output().rgba == sequential.read_output().rgba}};
}

}  // namespace pyro
