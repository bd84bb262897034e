// pyro bench schedule SCENE [--frames N] [--threads T] [--width W] [--height H] --json
// The parallel schedule against the sequential one in the same run (tools/bench/bench_schedule.h).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "tools/bench/bench_schedule.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ScheduleCommandArgs : ScheduleBenchArgs {
  bool json = false;
};

}  // namespace

void add_bench_schedule_command(CLI::App& bench) {
  auto args = std::make_shared<ScheduleCommandArgs>();
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
    const nlohmann::json r = bench_schedule(*args, print_note, terminal_progress());
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
