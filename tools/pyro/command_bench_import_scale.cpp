// pyro bench import-scale [--voxels N] [--keep FILE] [--source FILE] [--error E] [--error-size N]
//                         [--error-samples N] [--threads T] [--json]
// The VDB import at production sizes (tools/bench/import_scale.h): a synthetic file of at
// least N active voxels read sparse and imported, voxels per second and peak resident memory.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/bench_text.h"
#include "tools/bench/import_scale.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void print_import_scale_note(const std::string& line) { std::fprintf(stderr, "pyro bench import-scale: %s\n", line.c_str()); }

}  // namespace

void add_bench_import_scale_command(CLI::App& bench) {
  struct Args {
    ImportScaleOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  ImportScaleOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand(
      "import-scale", "A synthetic VDB of at least N active voxels read sparse and imported: voxels per second, "
                      "peak resident memory");
  cmd->add_option("--voxels", o.voxels, "Active voxels in the synthetic file (default 2e8)")
      ->check(CLI::Range(uint64_t(1000), uint64_t(4000000000)));
  cmd->add_option("--keep", o.keep, "Keep the synthetic file here (reused when it exists)");
  cmd->add_option("--source", o.source, "The small .vdb to resample (default: the Disney cloud beside the "
                                        "checkout, else the procedural cloud)");
  cmd->add_option("--error", o.error, "The import's error target (default 0.03)")->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--error-size", o.error_size,
                  "Width and height of the views where the import's error is measured (0: not measured; default 256)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--error-samples", o.error_samples, "Paths per pixel of the truth (default 256)")
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--threads", o.threads, "Import threads (0: one per core)")->check(CLI::Range(0, 256));
  cmd->add_flag("--json", args->json, "Print one JSON object");
  cmd->callback([args] {
    args->options.progress = terminal_progress();
    args->options.on_note = print_import_scale_note;
    args->options.progress_fd = STDERR_FILENO;
    const nlohmann::json j = bench_import_scale(args->options);
    write_result(j, import_scale_text(j), args->json);
  });
}

}  // namespace pyro::cli
