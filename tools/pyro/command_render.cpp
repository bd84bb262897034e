// pyro render SCENE --out DIR [--width W] [--height H] [--frames N | --frames A:B] [--json]
//
// Frames are rendered into a temporary folder beside DIR and moved into DIR only when every
// frame has been written: a failure (or a refusal) leaves DIR as it was.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "components/draw_list.h"
#include "engine/core/trace_events.h"
#include "engine/core/user_error.h"
#include "engine/io/text_file.h"
#include "systems/scene/scene_loader.h"
#include "systems/quality/quality_measurement.h"
#include "systems/quality/quality_picker.h"
#include "systems/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/frame_range.h"
#include "engine/io/staging_folder.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/trace_path.h"

namespace pyro::cli {

namespace {

struct RenderArgs {
  std::string scene;
  std::string out;
  int width = 0, height = 0;
  std::string frames = "1";
  bool json = false;
  std::string trace;  // --trace FILE: Chrome trace-event JSON of the session
  RuntimeOptions runtime;
};

std::string frame_name(int f) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d", f);
  return name;
}

void run_render(const RenderArgs& a) {
  // Everything the user can get wrong is checked before anything is written.
  const FrameRange range = parse_frame_range(a.frames, "--frames");
  SceneDescription scene = load_scene(a.scene);
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw UserError(a.out, "--out", "expected a folder for the frames, found a file");
  if (!a.trace.empty()) check_trace_path(a.trace, "--trace");

  // A quality target (scene key quality.max_rmse) picks the layer scale, footprint size and time
  // step: from the cache, or measured now and cached (systems/quality/quality_picker.h).
  std::optional<QualityPick> quality;
  int substeps = 1;
  if (scene.quality.given()) {
    quality = pick_quality(scene, a.width > 0 ? a.width : scene.width,
                           a.height > 0 ? a.height : scene.height, scene.quality.max_rmse,
                           shared_headless_context().description());
    scene = apply_quality_settings(scene, quality->settings);
    substeps = quality->settings.substeps;
    std::fprintf(stderr,
                 "pyro: quality: max RMSE %g -> layer scale %g, footprint %d, %d step(s) per frame; "
                 "expected RMSE %.4f against the %s (%s)%s\n",
                 quality->max_rmse, quality->settings.layer_scale, quality->settings.footprint_size,
                 substeps, quality->expected_rmse,
                 gaussian_particles(scene) ? "CPU reference" : "converged GL render",
                 quality->from_cache ? "cached" : "measured now",
                 quality->met ? "" : "; no candidate met the target, the most accurate was picked");
  }

  const auto t0 = std::chrono::steady_clock::now();
  RuntimeOptions options = a.runtime;
  options.readback = false;
  options.width_override = a.width;
  options.height_override = a.height;
  options.profile = !a.trace.empty();
  SceneRuntime runtime(scene, options);  // refuses a scene over its budget (scene_budget.h)

  StagingFolder staging(a.out);
  nlohmann::json files = nlohmann::json::array();
  const int count = range.count();
  Progress progress("render " + scene.name, static_cast<size_t>(count));
  // Frame f is the state after f steps whatever the range: the frames before the first are
  // simulated (same systems, same order) but neither drawn nor written.
  // With a finer time step (quality substeps k), frame f is the runtime's frame f * k.
  const auto runtime_frame = [&](int f) { return static_cast<uint64_t>(f) * static_cast<uint64_t>(substeps); };
  // With motion blur each output blends the frames before it, so those are drawn (not written)
  // too: frames A..B then equal the same frames of a full run.
  if (scene.render.motion_blur > 0.0f)
    for (int g = 0; g < range.first; ++g) {
      while (runtime.frame() < runtime_frame(g)) runtime.simulate_step();
      runtime.step();
    }
  while (runtime.frame() < runtime_frame(range.first)) runtime.simulate_step();
  for (int f = range.first; f <= range.last; ++f) {
    while (runtime.frame() < runtime_frame(f)) runtime.simulate_step();
    runtime.step();
    for (const std::string& path :
         runtime.write_png((staging.path() / frame_name(f)).string()))
      files.push_back((fs::path(a.out) / fs::path(path).filename()).string());
    progress.update(static_cast<size_t>(f - range.first + 1));
  }
  progress.finish();
  staging.commit();
  if (!a.trace.empty())
    write_text_file(a.trace, chrome_trace_json(runtime.trace(), "pyro render " + scene.file));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const auto* lists = runtime.world().try_resource<EyeDrawLists>();
  const size_t particles = lists && !lists->eyes.empty() ? lists->eyes[0].size() : 0;
  const RenderSettings& rs = runtime.settings();
  std::string stereo;
  for (const auto& [name, mode] : stereo_mode_names())
    if (mode == rs.stereo_mode) stereo = name;
  nlohmann::json systems = nlohmann::json::array();
  for (const auto& s : runtime.schedule().stats())
    systems.push_back({{"name", s.name}, {"phase", ecs::phase_name(s.phase)}, {"mean_ms", s.mean_ms()}});
  nlohmann::json summary = {
      {"scene", scene.file},
      {"name", scene.name},
      {"out", a.out},
      {"frames", count},
      {"first_frame", range.first},
      {"last_frame", range.last},
      {"width", rs.width},
      {"height", rs.height},
      {"stereo", stereo},
      {"billboards", rs.alignment == BillboardAlignment::viewplane ? "viewplane" : "viewpoint"},
      {"layer_scale", rs.layer_scale},
      {"particles", particles},
      {"files", files},
      {"seconds", seconds},
      {"ms_per_frame", seconds * 1000.0 / count},
      {"systems", systems},
      {"renderer", shared_headless_context().description()}};
  if (!a.trace.empty()) summary["trace"] = a.trace;
  if (quality) {
    summary["quality"] = {{"max_rmse", quality->max_rmse},
                          {"settings", to_json(quality->settings)},
                          {"expected_rmse", quality->expected_rmse},
                          {"met", quality->met},
                          {"ground_truth", quality->ground_truth},
                          {"from_cache", quality->from_cache}};
  }
  if (a.json) {
    std::printf("%s\n", summary.dump().c_str());
  } else {
    std::printf("rendered %d frame(s) of %s (%dx%d %s, %zu particles) into %s in %.2f s\n",
                count, scene.file.c_str(), rs.width, rs.height, stereo.c_str(), particles,
                a.out.c_str(), seconds);
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to PNG frames");
  cmd->add_option("scene", args->scene, "Scene file (JSON), e.g. content/scenes/fog.json")->required();
  cmd->add_option("--out", args->out, "Folder for frame_0000.png, frame_0001.png, ...")->required();
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", args->frames,
                  "N: frames 0..N-1; A:B: frames A..B inclusive (simulated from frame 0, only A..B "
                  "written, named frame_A.png ...)");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  cmd->add_option("--trace", args->trace,
                  "Write a Chrome trace-event JSON file (opens in Perfetto): one span per system "
                  "and GPU pass per frame");
  add_render_options(cmd, args->runtime);
  cmd->callback([args] { run_render(*args); });
}

}  // namespace pyro::cli
