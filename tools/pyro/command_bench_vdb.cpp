// pyro bench vdb FILE [--grid NAME] [--error E] [--width W] [--height H] [--json]
// Splats, the CPU reference and OpenVDB's vdb_render on one view (tools/bench/bench_vdb.h).
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_vdb.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void print_bench_vdb_note(const std::string& note) {
  std::fprintf(stderr, "pyro bench vdb: %s\n", note.c_str());
}

void run_bench_vdb(VdbBenchOptions options, bool json) {
  options.progress = terminal_progress();
  options.on_note = print_bench_vdb_note;
  const nlohmann::json j = bench_vdb(options);
  if (json) {
    write_stdout(j.dump() + "\n");
    return;
  }
  const double splat = j["splat_ms"].get<double>(), vdb = j["vdb_render_ms"].get<double>();
  std::printf("splat %.1f ms, reference %.1f ms, vdb_render %.1f ms: %.1fx faster than vdb_render, "
              "RMSE %.4f\n",
              splat, j["reference_ms"].get<double>(), vdb, vdb / splat,
              j["rmse_vs_reference"].get<double>());
  if (const nlohmann::json& v = j["rmse_vs_vdb_render"]; !v.is_null())
    std::printf("against vdb_render (no ambient, black behind): RMSE splats %.4f, CPU reference %.4f\n",
                v["splats"].get<double>(), v["reference"].get<double>());
}

}  // namespace

void add_bench_vdb_command(CLI::App& bench) {
  struct BenchVdbArgs {
    VdbBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<BenchVdbArgs>();
  VdbBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand("vdb", "Splatting vs the CPU reference vs OpenVDB's vdb_render on one view");
  cmd->add_option("file", o.file, "OpenVDB file (.vdb)")->required();
  cmd->add_option("--grid", o.grid, "Grid name");
  cmd->add_option("--grid-index", o.grid_index, "Grid position in the file, from 0");
  cmd->add_option("--error", o.error, "Import error target (default 0.03)");
  cmd->add_option("--width", o.width, "Image width (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", o.height, "Image height (default 512)")->check(CLI::Range(1, 8192));
  cmd->add_option("--vdb-render", o.vdb_render, "The vdb_render program (default: from PATH)");
  cmd->add_option("--vdb-step", o.vdb_render_step, "vdb_render's step along the view ray, in voxels (default 0.5)")
      ->check(CLI::Range(0.01, 16.0));
  cmd->add_option("--vdb-shadow-step", o.vdb_render_shadow_step,
                  "vdb_render's step towards the light, in voxels (default 1)")
      ->check(CLI::Range(0.01, 16.0));
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_bench_vdb(args->options, args->json); });
}

}  // namespace pyro::cli
