// pyro bench explosion-shadows [SCENE] [--width W] [--height H] [--layer-scale S] [--frames N]
//                                      [--error-frames N] [--json]
// The explosion's media shadowed by each shadow setting, timed against shadows off and scored
// against exact per-fragment shadows (tools/bench/bench_explosion_shadows.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_explosion_shadows.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void run_bench_explosion_shadows(ExplosionShadowsBenchOptions options, bool json) {
  options.progress = terminal_progress();
  const nlohmann::json j = bench_explosion_shadows(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::printf("%s at %dx%d, layers at %.3g: shadows off %.1f fps, RMSE %.4f against exact shadows\n",
              options.scene.c_str(), options.width, options.height, double(options.layer_scale),
              j["off"]["fps"].get<double>(), j["off"]["rmse_vs_truth"].get<double>());
  for (const nlohmann::json& row : j["settings"])
    std::printf("  %-5s %4dx%-3d %d fire lights %6.1f fps (%.2fx shadows off), RMSE %.4f\n",
                row["method"].get<std::string>().c_str(), row["map_size"].get<int>(),
                row["map_slices"].get<int>(), row["fire_lights"].get<int>(), row["fps"].get<double>(),
                row["fps_over_off"].get<double>(), row["rmse_vs_truth"].get<double>());
}

}  // namespace

void add_bench_explosion_shadows_command(CLI::App& bench) {
  struct Args {
    ExplosionShadowsBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  ExplosionShadowsBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand(
      "explosion-shadows",
      "The explosion's dust and smoke shadowed by each shadow setting: fps against shadows off, RMSE against exact shadows");
  cmd->add_option("scene", o.scene, "Scene with explosion media (default content/scenes/explosion.json)");
  cmd->add_option("--width", o.width, "Image width (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", o.height, "Image height (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--layer-scale", o.layer_scale, "Media layer scale of the measured settings (default 0.5)")
      ->check(CLI::IsMember({0.125f, 0.25f, 0.5f, 1.0f}));
  cmd->add_option("--frames", o.frames, "Timed frames of each setting (default 60)")->check(CLI::Range(1, 100000));
  cmd->add_option("--error-frames", o.error_frames, "Frames where RMSE is measured (default 4)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_explosion_shadows(args->options, args->json); });
}

}  // namespace pyro::cli
