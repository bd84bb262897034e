// pyro bench cycles-fire FILE... [--width W] [--height H] [--cycles-samples N] [--error E]
//     [--emitting-fraction F] [--blender PATH] [--json]
// A fire cache as the engine shows it against Cycles' black-body render (tools/bench/bench_cycles_fire.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_cycles_fire.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void print_fire_scores(const nlohmann::json& f) {
  std::printf("  %s (\"%s\", hottest %.0f K): the vdb template clips %d of %d pixels\n",
              f["file"].get<std::string>().c_str(), f["temperature_grid"].get<std::string>().c_str(),
              f["hottest_kelvin"].get<double>(), f["template_clipped_pixels"].get<int>(),
              f["template_pixels"].get<int>());
  if (!f.contains("chromaticity_difference")) {
    std::printf("    no score (Cycles failed, or nothing glows)\n");
    return;
  }
  std::printf("    %d emitting pixels: xy ours (%.4f, %.4f), Cycles' (%.4f, %.4f), difference %.4f; "
              "per pixel median %.4f, 90th percentile %.4f; relative luminance RMSE %.3f\n",
              f["emitting_pixels"].get<int>(), f["chromaticity_ours"][0].get<double>(),
              f["chromaticity_ours"][1].get<double>(), f["chromaticity_cycles"][0].get<double>(),
              f["chromaticity_cycles"][1].get<double>(), f["chromaticity_difference"].get<double>(),
              f["pixel_chromaticity_difference_median"].get<double>(),
              f["pixel_chromaticity_difference_p90"].get<double>(), f["relative_luminance_rmse"].get<double>());
}

void run_bench_cycles_fire(CyclesFireBenchOptions options, bool json) {
  options.progress = terminal_progress();
  options.on_note = [](const std::string& note) { std::fprintf(stderr, "pyro bench cycles-fire: %s\n", note.c_str()); };
  const nlohmann::json j = bench_cycles_fire(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::printf("fire as the vdb template shows it against Cycles' black-body render (%d samples), %dx%d\n",
              options.cycles_samples, options.width, options.height);
  for (const nlohmann::json& f : j["files"]) print_fire_scores(f);
}

}  // namespace

void add_bench_cycles_fire_command(CLI::App& bench) {
  struct Args {
    CyclesFireBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CyclesFireBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand(
      "cycles-fire", "A fire cache as the vdb template shows it against Cycles' black-body render (needs blender)");
  cmd->add_option("files", o.files, "OpenVDB files with a temperature grid (.vdb)")->required();
  cmd->add_option("--width", o.width, "Image width (default 160)")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", o.height, "Image height (default 120)")->check(CLI::Range(1, 4096));
  cmd->add_option("--cycles-samples", o.cycles_samples, "Samples per pixel of the Cycles render (default 64)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--error", o.error, "The import's error target (default 0.03, the vdb template's)")
      ->check(CLI::Range(1e-4, 1.0));
  cmd->add_option("--emitting-fraction", o.emitting_fraction,
                  "Pixels scored: Cycles' luminance at least this fraction of its largest (default 0.05)")
      ->check(CLI::Range(1e-4, 1.0));
  cmd->add_option("--blender", o.blender, "The blender program (default: blender on PATH)");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_cycles_fire(args->options, args->json); });
}

}  // namespace pyro::cli
