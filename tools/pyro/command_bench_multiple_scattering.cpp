// pyro bench multiple-scattering FILE [--directions N] [--samples N] [--width W] [--height H]
//     [--extinction K] [--albedo A] [--anisotropy G] [--octaves N] [--attenuation A]
//     [--contribution B] [--eccentricity C] [--images DIR] [--json]
// Single scattering and the octave approximation against the path-traced truth
// (tools/bench/bench_multiple_scattering.h).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "tools/bench/bench_multiple_scattering.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void run_bench_multiple_scattering(MultipleScatteringBenchOptions options, bool json) {
  if (!options.images.empty() && !std::filesystem::is_directory(options.images))
    throw UserError(options.images, "--images", "an existing folder for the frames");
  OutputGate()
      .reads(options.file, "the OpenVDB file")
      .writes({options.images, "--images", OutputShape::container})
      .check();
  options.progress = terminal_progress();
  options.on_note = [](const std::string& note) {
    std::fprintf(stderr, "pyro bench multiple-scattering: %s\n", note.c_str());
  };
  const nlohmann::json j = bench_multiple_scattering(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::printf("%s at %dx%d, %d paths per pixel, albedo %.3g, g %.2g, %d octaves:\n",
              options.file.c_str(), options.width, options.height, options.samples, options.albedo,
              options.sun.anisotropy, options.sun.octaves.octaves);
  for (const nlohmann::json& d : j["directions"])
    std::printf("  sun (%.2f, %.2f, %.2f): RMSE single scattering %.4f, octaves %.4f "
                "(path traced in %.1f s, Monte Carlo error %.4f)\n",
                d["direction"][0].get<double>(), d["direction"][1].get<double>(), d["direction"][2].get<double>(),
                d["single_scattering_rmse"].get<double>(), d["octaves_rmse"].get<double>(),
                d["path_traced_seconds"].get<double>(), d["monte_carlo_error"].get<double>());
}

}  // namespace

void add_bench_multiple_scattering_command(CLI::App& bench) {
  struct Args {
    MultipleScatteringBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  MultipleScatteringBenchOptions& o = args->options;
  ScatteringOctaves& oct = o.sun.octaves;
  CLI::App* cmd = bench.add_subcommand(
      "multiple-scattering", "Single scattering and the octave approximation against the path-traced truth");
  cmd->add_option("file", o.file, "OpenVDB file (.vdb)")->required();
  cmd->add_option("--grid", o.grid, "Grid name");
  cmd->add_option("--grid-index", o.grid_index, "Grid position in the file, from 0");
  cmd->add_option("--directions", o.directions, "Sun directions, 360/N degrees apart (default 3)")
      ->check(CLI::Range(1, 360));
  cmd->add_option("--samples", o.samples, "Paths per pixel of the truth (default 64)")->check(CLI::Range(2, 1 << 20));
  cmd->add_option("--width", o.width, "Image width (default 128)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", o.height, "Image height (default 128)")->check(CLI::Range(1, 8192));
  cmd->add_option("--extinction", o.extinction, "Extinction per world unit per unit density (default: the grid's)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--albedo", o.albedo, "Single-scattering albedo (default 0.95)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--anisotropy", o.sun.anisotropy, "Henyey-Greenstein g (default 0.6)")->check(CLI::Range(-0.99, 0.99));
  cmd->add_option("--octaves", oct.octaves, "Octaves, 1 = single scattering (default 4)")->check(CLI::Range(1, 16));
  cmd->add_option("--attenuation", oct.attenuation, "a: optical depth scale per octave (default 0.25)");
  cmd->add_option("--contribution", oct.contribution, "b: weight per octave (default 0.5)");
  cmd->add_option("--eccentricity", oct.eccentricity, "c: phase eccentricity per octave (default 0.5)");
  cmd->add_option("--images", o.images, "Folder to write each direction's frames into as PNG");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_multiple_scattering(args->options, args->json); });
}

}  // namespace pyro::cli
