// pyro profile SCENE [--frames N] [--warmup K] [--width W] [--height H] [--sync-timing] [--json]
//                    [--trace FILE] [render options]
//
// A profiling run (SceneRuntime with RuntimeOptions::profile) of the scene opened as every
// command opens it (systems/runtime/open_scene/open_scene.h: a quality target's pick applied, and
// reported under "quality" in the JSON summary): K warm-up frames (shader
// compilation, first allocations; not counted), then N frames, every system timed on the CPU
// and every GL pass on the GPU (timer queries). Prints per system the mean, median, 95th
// percentile and maximum milliseconds, per GPU pass the same plus the fragments it drew
// (GL_SAMPLES_PASSED: fragments that passed the depth test), the live particles per source
// and per medium, and the particle pools' memory. With --json the last line is one object;
// --trace writes the run (warm-up included) as Chrome trace-event JSON.
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/trace_events.h"
#include "engine/io/text_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "tools/bench/profile_report.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/scene_inputs.h"
#include "tools/pyro/trace_path.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ProfileArgs {
  std::string scene;
  int frames = 30;
  int warmup = 1;
  int width = 0, height = 0;
  bool json = false;
  std::string trace;  // --trace FILE
  RuntimeOptions runtime;
};

// The report as tables: systems, GPU passes, particles.
void print_report(const nlohmann::json& r) {
  std::printf("%-20s %-10s %9s %9s %9s %9s %9s\n", "system", "phase", "mean ms", "p95 ms",
              "max ms", "GPU mean", "GPU p95");
  for (const auto& row : r["systems"]) {
    std::printf("%-20s %-10s %9.3f %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                row["phase"].get<std::string>().c_str(), row["mean_ms"].get<double>(),
                row["p95_ms"].get<double>(), row["max_ms"].get<double>());
    if (row.contains("gpu_mean_ms"))
      std::printf(" %9.3f %9.3f\n", row["gpu_mean_ms"].get<double>(), row["gpu_p95_ms"].get<double>());
    else
      std::printf(" %9s %9s\n", "-", "-");
  }
  std::printf("%-32s %9s %9s %14s\n", "GPU pass", "mean ms", "p95 ms", "fragments");
  for (const auto& row : r["gpu_passes"]) {
    std::printf("%-32s %9.3f %9.3f", row["name"].get<std::string>().c_str(),
                row["mean_ms"].get<double>(), row["p95_ms"].get<double>());
    if (row.contains("fragments_mean"))
      std::printf(" %14.0f\n", row["fragments_mean"].get<double>());
    else
      std::printf(" %14s\n", "-");
  }
  const nlohmann::json& p = r["particles"];
  std::printf("particles: %llu live of %llu slots; %zu bytes per slot, %.1f bytes of pool per live particle\n",
              p["live"].get<unsigned long long>(), p["capacity"].get<unsigned long long>(),
              r["memory"]["bytes_per_particle_slot"].get<size_t>(),
              r["memory"]["pool_bytes_per_live_particle"].get<double>());
  for (const auto& s : p["sources"])
    std::printf("  %-18s %llu live of %llu\n", s["name"].get<std::string>().c_str(),
                s["live"].get<unsigned long long>(), s["capacity"].get<unsigned long long>());
}

void run_profile(const ProfileArgs& a) {
  if (!a.trace.empty()) check_trace_path(a.trace, "--trace");
  const SceneDescription scene = load_scene(a.scene);
  if (!a.trace.empty()) refuse_output_over_inputs(a.trace, "--trace", scene_inputs(a.scene, scene));
  OpenSceneOptions open;
  open.runtime = a.runtime;
  open.runtime.readback = false;
  open.runtime.width_override = a.width;
  open.runtime.height_override = a.height;
  open.runtime.profile = true;
  open.description = scene;
  open.on_note = print_note;
  const OpenedScene opened = open_scene(a.scene, open);  // with the scene's quality pick
  SceneRuntime& runtime = *opened.runtime;
  for (int f = 0; f < a.warmup + a.frames; ++f) runtime.step();
  const RenderSettings& rs = runtime.settings();
  nlohmann::json summary = {{"scene", scene.file},   {"frames", a.frames},
                            {"warmup", a.warmup},    {"width", rs.width},
                            {"height", rs.height},   {"layer_scale", rs.layer_scale},
                            {"sync_timing", a.runtime.sync_timing}};
  summary.update(profile_report(runtime, static_cast<uint64_t>(a.warmup)));
  if (opened.quality) summary["quality"] = quality_pick_summary(*opened.quality);
  summary["renderer"] = shared_headless_context().description();
  std::printf("%s: %d frames (after %d warm-up) at %dx%d, frame %.2f ms mean, %.2f ms p95\n",
              scene.file.c_str(), a.frames, a.warmup, rs.width, rs.height,
              summary["frame_mean_ms"].get<double>(), summary["frame_p95_ms"].get<double>());
  if (!a.trace.empty()) {
    write_text_file(a.trace, chrome_trace_json(runtime.trace(), "pyro profile " + scene.file));
    summary["trace"] = a.trace;
  }
  print_report(summary);
  if (a.json) write_stdout(summary.dump() + "\n");
}

}  // namespace

void add_profile_command(CLI::App& app) {
  auto args = std::make_shared<ProfileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "profile", "Time every system and GPU pass over a run of frames: mean and 95th percentile");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--frames", args->frames, "Frames measured (after the warm-up)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--warmup", args->warmup, "Frames run first and not counted")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_flag("--sync-timing", args->runtime.sync_timing,
                "Finish the GPU's work after every system, so each system's CPU span includes the "
                "GPU work it issued (removes CPU/GPU overlap)");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  cmd->add_option("--trace", args->trace,
                  "Write a Chrome trace-event JSON file (opens in Perfetto): one span per system "
                  "per frame, one track per worker thread, the GPU passes on their own track");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_profile(*args); });
}

}  // namespace pyro::cli
