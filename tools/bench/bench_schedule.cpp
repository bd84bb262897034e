// pyro bench schedule SCENE [--frames N] [--threads T] [--width W] [--height H] --json
// The parallel schedule against the sequential one in the same run: two runtimes of the scene
// (opened as every command opens it, with one quality pick),
// one with T threads (0: one per core) and one with 1, stepped in turn (ABAB..., so that both
// see the same machine noise), the GPU finished after every frame. Reports the median ms per
// whole frame and per frame of the CPU phases (spawn to sort: the systems that may run
// concurrently; the GL phases run on the calling thread either way), their ratios, and whether
// the two produced the same output bytes.
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "systems/open_scene/open_scene.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ScheduleBenchArgs {
  std::string scene;
  int frames = 60;
  int threads = 0;
  int width = 0, height = 0;
  bool json = false;
};

double median(std::vector<double> v) {
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

nlohmann::json bench_schedule(const ScheduleBenchArgs& a) {
  // Both runtimes open the scene as every command does, with one quality pick.
  OpenSceneOptions open;
  open.runtime.readback = false;
  open.runtime.width_override = a.width;
  open.runtime.height_override = a.height;
  open.runtime.threads = a.threads;
  open.on_note = print_note;
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
  Progress progress("bench schedule", size_t(a.frames));
  for (int f = 0; f < a.frames; ++f) {
    timed_step(parallel, par);
    timed_step(sequential, seq);
    progress.update(size_t(f) + 1);
  }
  progress.finish();
  const double par_ms = median(par.frame_ms), seq_ms = median(seq.frame_ms);
  const double par_cpu = median(par.cpu_ms), seq_cpu = median(seq.cpu_ms);
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

}  // namespace

void add_bench_schedule_command(CLI::App& bench) {
  auto args = std::make_shared<ScheduleBenchArgs>();
  CLI::App* cmd = bench.add_subcommand(
      "schedule", "Frame time of the parallel schedule against the sequential one, in one run");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--frames", args->frames, "Timed frames of each schedule (default 60)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--threads", args->threads, "Threads of the parallel schedule (0: one per core)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--width", args->width, "Width (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Height (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_flag("--json", args->json, "Print one JSON object");
  cmd->callback([args] {
    const nlohmann::json r = bench_schedule(*args);
    if (args->json) {
      write_stdout(r.dump() + "\n");
      return;
    }
    std::printf(
        "%s, %d threads: %.2f ms per frame parallel, %.2f sequential (ratio %.3f); CPU "
        "phases %.3f ms vs %.3f (ratio %.3f); same output: %s\n",
        args->scene.c_str(), r["threads"].get<int>(), r["ms_per_frame_parallel"].get<double>(),
        r["ms_per_frame_sequential"].get<double>(), r["frame_ratio"].get<double>(),
        r["cpu_phases_ms_parallel"].get<double>(), r["cpu_phases_ms_sequential"].get<double>(),
        r["cpu_phases_ratio"].get<double>(), r["results_agree"].get<bool>() ? "yes" : "no");
  });
}

}  // namespace pyro::cli
