// pyro bench relight FILE [--fitted] [--directions N] [--error E] [--grid NAME] [--width W] [--height H]
//                         [--frames N] [--shadows map|rays|none] [--splat-sunlight fragments|vertices]
//                         [--json]
// An OpenVDB grid imported once and relit from N sun directions by the light phase
// (tools/bench/bench_relight.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_relight.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/render_options.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void run_bench_relight(RelightBenchOptions options, bool json) {
  options.progress = terminal_progress();
  options.on_note = [](const std::string& note) { std::fprintf(stderr, "pyro bench relight: %s\n", note.c_str()); };
  const nlohmann::json j = bench_relight(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  std::printf("%zu particles relit from %d directions at %dx%d (%s): max RMSE %.4f against the reference, "
              "%.1f fps relit, %.1f fps unlit (%.2fx)\n",
              j["particles"].get<size_t>(), options.directions, options.width, options.height,
              j["shadows"]["method"].get<std::string>().c_str(), j["max_rmse_vs_reference"].get<double>(),
              j["fps"].get<double>(), j["unlit_fps"].get<double>(), j["fps_over_unlit"].get<double>());
}

}  // namespace

void add_bench_relight_command(CLI::App& bench) {
  struct Args {
    RelightBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  RelightBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand(
      "relight", "A VDB grid imported once and relit by the light phase from N sun directions, against the reference");
  cmd->add_option("file", o.file, "OpenVDB file (.vdb)")->required();
  cmd->add_option("--grid", o.grid, "Grid name");
  cmd->add_option("--grid-index", o.grid_index, "Grid position in the file, from 0");
  cmd->add_option("--error", o.error, "Import error target (default 0.03)")->check(CLI::Range(1e-4, 1.0));
  cmd->add_option("--directions", o.directions, "Sun directions, 360/N degrees apart (default 8)")
      ->check(CLI::Range(1, 360));
  cmd->add_option("--width", o.width, "Image width (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", o.height, "Image height (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--frames", o.frames, "Timed frames, relit and unlit (default 16)")->check(CLI::Range(1, 100000));
  add_enum_option<ShadowMethod>(
      cmd, "--shadows", [&o](ShadowMethod m) { o.shadows.method = m; }, "Shadow method (default: map)");
  add_enum_option<SplatSunlight>(
      cmd, "--splat-sunlight", [&o](SplatSunlight s) { o.shadows.splat_sunlight = s; },
      "Where the splats' sunlight is evaluated (default: the scene format's default)");
  cmd->add_flag("--fitted", o.fitted,
                "Relight the anisotropic Gaussians import-vdb fits, instead of the octree's isotropic particles");
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_relight(args->options, args->json); });
}

}  // namespace pyro::cli
