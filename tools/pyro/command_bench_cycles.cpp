// pyro bench cycles FILE... [--directions N] [--samples N] [--cycles-samples N] [--bounces N]
//     [--width W] [--height H] [--albedo A] [--anisotropy G] [--block B] [--offset-ours V] [--grid NAME]
//     [--blender PATH] [--json]
// The engine's path-traced truth against Blender's Cycles (tools/bench/bench_cycles.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_cycles.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

std::string number_or_dash(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v.get<double>());
  return buf;
}

void run_bench_cycles(CyclesBenchOptions options, bool json) {
  options.progress = terminal_progress();
  options.on_note = [](const std::string& note) { std::fprintf(stderr, "pyro bench cycles: %s\n", note.c_str()); };
  const nlohmann::json j = bench_cycles(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::printf("path tracer (%d paths per pixel) against Cycles (%d samples, %d bounces), %dx%d, albedo %.3g, g %.2g\n",
              options.samples, options.cycles_samples, options.bounces, options.width, options.height,
              options.albedo, options.anisotropy);
  for (const nlohmann::json& f : j["files"])
    for (const nlohmann::json& d : f["directions"])
      std::printf("  %s, sun (%.2f, %.2f, %.2f): RMSE %s; from noise alone %s (ours %.4f, Cycles' %s); "
                  "%dx%d block means: RMSE %s, from noise alone %s, bias %s; mean difference %s +- %s\n",
                  f["file"].get<std::string>().c_str(), d["direction"][0].get<double>(),
                  d["direction"][1].get<double>(), d["direction"][2].get<double>(),
                  number_or_dash(d["rmse_vs_cycles"]).c_str(), number_or_dash(d["noise_rmse"]).c_str(),
                  d["monte_carlo_error"].get<double>(), number_or_dash(d["cycles_noise"]).c_str(), options.block,
                  options.block, number_or_dash(d["block_rmse_vs_cycles"]).c_str(),
                  number_or_dash(d["block_noise_rmse"]).c_str(), number_or_dash(d["bias_rmse"]).c_str(),
                  number_or_dash(d["mean_difference"]).c_str(), number_or_dash(d["mean_difference_error"]).c_str());
}

}  // namespace

void add_bench_cycles_command(CLI::App& bench) {
  struct Args {
    CyclesBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CyclesBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand("cycles", "The path-traced truth against Blender's Cycles (needs blender)");
  cmd->add_option("files", o.files, "OpenVDB files (.vdb)")->required();
  cmd->add_option("--grid", o.grid, "Grid name (default: each file's first float grid)");
  cmd->add_option("--directions", o.directions, "Sun directions, 360/N degrees apart (default 3)")
      ->check(CLI::Range(1, 360));
  cmd->add_option("--samples", o.samples, "Paths per pixel of the engine's path tracer (default 512)")
      ->check(CLI::Range(2, 1 << 20));
  cmd->add_option("--cycles-samples", o.cycles_samples, "Samples per pixel of each Cycles render (default 512)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--bounces", o.bounces, "Cycles' volume bounces (default 256)")->check(CLI::Range(0, 1024));
  cmd->add_option("--width", o.width, "Image width (default 128)")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", o.height, "Image height (default 128)")->check(CLI::Range(1, 4096));
  cmd->add_option("--albedo", o.albedo, "Single-scattering albedo (default 0.95)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--anisotropy", o.anisotropy, "Henyey-Greenstein g (default 0.6)")->check(CLI::Range(-0.99, 0.99));
  cmd->add_option("--block", o.block, "Side of the square blocks of pixels whose means are scored too (default 8)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--offset-ours", o.offset_ours,
                  "Add this to the engine's image where the medium shows: a known bias, to see what the scores see "
                  "(default 0)")
      ->check(CLI::Range(-1.0, 1.0));
  cmd->add_option("--blender", o.blender, "The blender program (default: blender on PATH)");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_cycles(args->options, args->json); });
}

}  // namespace pyro::cli
