// pyro bench cycles-scene SCENE [--frame N] [--width W] [--height H] [--samples N] [--bounces N]
//     [--voxel-error E] [--image FILE] [--blender PATH] [--json]
// One whole frame of a scene against Blender's Cycles, region by region
// (tools/bench/bench_cycles_scene.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_cycles_scene.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

std::string figure(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v.get<double>());
  return buf;
}

void run_bench_cycles_scene(CyclesSceneBenchOptions options, bool json) {
  options.progress = terminal_progress();
  options.on_note = [](const std::string& note) {
    std::fprintf(stderr, "pyro bench cycles-scene: %s\n", note.c_str());
  };
  const nlohmann::json j = bench_cycles_scene(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::string text = "frame " + std::to_string(j["frame"].get<int>()) + " of " + j["scene"].get<std::string>() +
                     " at " + std::to_string(j["width"].get<int>()) + "x" + std::to_string(j["height"].get<int>()) +
                     " against Cycles (" + std::to_string(options.samples) + " samples, " +
                     std::to_string(options.bounces) + " volume bounces)\n";
  text += "  frame RMSE " + figure(j["rmse"]) + " (Cycles' noise " + figure(j["cycles_noise"]) +
          "), sRGB-encoded " + figure(j["srgb_rmse"]) + "\n";
  if (j["regions"].is_object())
    for (const auto& [name, r] : j["regions"].items())
      text += "  " + name + ": " + std::to_string(r["pixels"].get<int>()) + " pixels, RMSE " + figure(r["rmse"]) +
              " (noise " + figure(r["cycles_noise"]) + "), mean difference " + figure(r["mean_difference"]) +
              ", share of the squared error " + figure(r["squared_error_share"]) + "\n";
  if (!j["largest_region"].is_null()) text += "  largest difference: " + j["largest_region"].get<std::string>() + "\n";
  for (const auto& a : j["approximations"]) text += "  approximation: " + a.get<std::string>() + "\n";
  write_stdout(text);
}

}  // namespace

void add_bench_cycles_scene_command(CLI::App& bench) {
  struct Args {
    CyclesSceneBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CyclesSceneBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand("cycles-scene", "One whole frame against Blender's Cycles (needs blender)");
  cmd->add_option("scene", o.scene, "Scene file (.json)")->required();
  cmd->add_option("--frame", o.frame, "Output frame (default 0)")->check(CLI::Range(0, 1 << 20));
  cmd->add_option("--width", o.width, "Frame width (default: the scene's aspect, 240 on the longer side)")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", o.height, "Frame height (default: the scene's aspect, 240 on the longer side)")->check(CLI::Range(1, 4096));
  cmd->add_option("--samples", o.samples, "Samples per pixel of each Cycles render (default 256)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--bounces", o.bounces, "Cycles' volume bounces (default 64)")->check(CLI::Range(0, 1024));
  cmd->add_option("--voxel-error", o.voxel_error,
                  "Column opacity error target of the media's grid (default 0.01)")
      ->check(CLI::Range(1e-4, 1.0));
  cmd->add_option("--image", o.image, "Write the engine's frame, Cycles' and the regions side by side (PNG)");
  cmd->add_option("--blender", o.blender, "The blender program (default: blender on PATH)");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_cycles_scene(args->options, args->json); });
}

}  // namespace pyro::cli
