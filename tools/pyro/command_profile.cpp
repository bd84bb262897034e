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
#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "tools/bench/bench_text.h"
#include "tools/bench/profile_report.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/scene_inputs.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/render_options.h"
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
void run_profile(const ProfileArgs& a) {
  const SceneDescription scene = load_scene(a.scene);
  OutputGate().reads(scene_inputs(a.scene, scene)).writes_file(a.trace, "--trace").check();
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
  write_stdout(profile_tables_text(summary));
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
