// pyro quality SCENE [--max-rmse E] [--width W] [--height H] [--no-cache] [--no-verify] [--json]
//
// Shows a quality target end to end: picks the cheapest settings meeting the
// target (systems/runtime/quality_picker/quality_picker.h; from the cache when this scene was measured on this
// machine), then checks the pick on frames the search never saw: its RMSE against the ground
// truth beside the full-resolution defaults' RMSE, and the time per frame of both, measured in
// this run, alternating, best of two runs each.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/quality_picker/quality_measurement.h"
#include "systems/runtime/quality_picker/quality_picker.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct QualityArgs {
  std::string scene;
  double max_rmse = 0.0;
  int width = 0, height = 0;
  bool no_cache = false;
  bool no_verify = false;
  bool json = false;
};

void run_quality(const QualityArgs& a) {
  const SceneDescription scene = load_scene(a.scene);
  const double target = a.max_rmse > 0.0 ? a.max_rmse : scene.quality.max_rmse;
  if (!(target > 0.0))
    throw UserError(a.scene, "/quality/max_rmse",
                    "expected an error target: \"quality\": {\"max_rmse\": E} in the scene, or --max-rmse E");
  const int width = a.width > 0 ? a.width : scene.width;
  const int height = a.height > 0 ? a.height : scene.height;
  RuntimeOptions prepare;  // the measurement's runtimes open a prepared scene
  prepare.on_note = print_note;
  prepare_scene_run(scene, prepare);
  const std::string renderer = shared_headless_context().description();
  const QualityPick pick =
      pick_quality(scene, width, height, target, renderer, !a.no_cache, QualitySearch{}, print_note);

  nlohmann::json summary = pick.to_json();
  summary["scene"] = scene.file;
  summary["width"] = width;
  summary["height"] = height;
  summary["renderer"] = renderer;
  std::printf("%s at %dx%d, max RMSE %g: layer scale %g, footprint %d, %d step(s) per frame%s; "
              "expected RMSE %.4f (%s)%s\n",
              scene.file.c_str(), width, height, target, pick.settings.layer_scale,
              pick.settings.footprint_size, pick.settings.substeps,
              shadow_choice_text(pick.settings.shadows).c_str(), pick.expected_rmse,
              pick.from_cache ? "cached" : "measured now",
              pick.met ? "" : "; NO candidate met the target: the most accurate one was picked");

  if (!a.no_verify) {
    const std::vector<int> frames = {5, 15, 25};
    const QualityGroundTruth truth(scene, width, height, frames);
    const double rmse = measure_rmse(scene, width, height, pick.settings, truth);
    const double defaults_rmse = measure_rmse(scene, width, height, pick.defaults, truth);
    double ms = 1e300, defaults_ms = 1e300;
    for (int run = 0; run < 2; ++run) {
      ms = std::min(ms, measure_ms_per_frame(scene, width, height, pick.settings, 8));
      defaults_ms = std::min(defaults_ms, measure_ms_per_frame(scene, width, height, pick.defaults, 8));
    }
    summary["verification"] = {{"frames", frames},
                               {"rmse", rmse},
                               {"meets_target", rmse <= target},
                               {"defaults_rmse", defaults_rmse},
                               {"ms_per_frame", ms},
                               {"defaults_ms_per_frame", defaults_ms},
                               {"speedup_vs_defaults", ms > 0.0 ? defaults_ms / ms : 0.0}};
    std::printf("verified on frames 5, 15, 25 against the %s: RMSE %.4f (%s the target %g); "
                "full-resolution defaults RMSE %.4f; %.2f ms per frame against %.2f ms (%.2fx)\n",
                truth.cpu_reference() ? "CPU reference" : "converged GL render", rmse,
                rmse <= target ? "meets" : "MISSES", target, defaults_rmse, ms, defaults_ms,
                ms > 0.0 ? defaults_ms / ms : 0.0);
  }
  if (a.json) write_stdout(summary.dump() + "\n");
}

}  // namespace

void add_quality_command(CLI::App& app) {
  auto args = std::make_shared<QualityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "quality", "Pick the cheapest settings meeting an image-error target, and verify the pick");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--max-rmse", args->max_rmse,
                  "RMSE target against the ground truth (default: the scene's quality.max_rmse)")
      ->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--width", args->width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 8192));
  cmd->add_flag("--no-cache", args->no_cache, "Measure even when the cache has the answer; write no cache");
  cmd->add_flag("--no-verify", args->no_verify, "Only pick: skip the check on other frames");
  cmd->add_flag("--json", args->json, "Print a JSON summary as the last line");
  cmd->callback([args] { run_quality(*args); });
}

}  // namespace pyro::cli
