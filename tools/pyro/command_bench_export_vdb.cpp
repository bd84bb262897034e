// pyro bench export-vdb SCENE [--frame F] [--error E] [--voxel-size H] [--import-error E2]
//                       [--width W] [--height H] [--json]
// The export's round trip measured: tools/export/vdb_round_trip.h does the work.
#include <memory>

#include "tools/export/vdb_round_trip.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/print_note.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct BenchExportVdbArgs {
  VdbRoundTripOptions options;
  bool json = false;
};

}  // namespace

void add_bench_export_vdb_command(CLI::App& bench) {
  auto a = std::make_shared<BenchExportVdbArgs>();
  CLI::App* cmd = bench.add_subcommand(
      "export-vdb", "A frame exported as OpenVDB, imported again and both drawn by the CPU reference: the opacity error");
  cmd->add_option("scene", a->options.scene, "Scene of Gaussian splats (clouds, fog, mist)")->required();
  cmd->add_option("--frame", a->options.frame, "The frame exported (default 0)")->check(CLI::Range(0, 999999));
  cmd->add_option("--error", a->options.error, "The export's --error (default 0.01)");
  cmd->add_option("--voxel-size", a->options.voxel_size, "The export's --voxel-size (default: chosen)");
  cmd->add_option("--import-error", a->options.import_error, "The import's error target (default 0.01)")
      ->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--width", a->options.width, "Width of the opacity images (default 160)")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", a->options.height, "Height of the opacity images (default 120)")->check(CLI::Range(1, 4096));
  cmd->add_flag("--json", a->json, "Print a JSON summary");
  cmd->callback([a] {
    const VdbRoundTrip r = measure_vdb_round_trip(a->options, print_note);
    write_stdout(a->json ? r.json.dump() + "\n" : r.text);
  });
}

}  // namespace pyro::cli
