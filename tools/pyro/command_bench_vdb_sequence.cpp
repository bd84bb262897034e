// pyro bench vdb-sequence [--frames 25,100] [--side N] [--error E] [--keep DIR] [--json]
// The animated VDB import (tools/bench/vdb_sequence_bench.h): frames per second and peak
// resident memory for sequences of several lengths, each imported in a process of its own.
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "tools/bench/vdb_sequence_bench.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

void print_vdb_sequence(const nlohmann::json& j) {
  const double mib = double(1 << 20);
  std::printf("a %d^3 puff's motion, written at each length in %.1f s in all\n", j["side"].get<int>(),
              j["generate_seconds"].get<double>());
  for (const auto& r : j["runs"])
    std::printf("%4llu frames: %.2f s, %.2f frames/s (check %.2f s, read %.2f s, import %.2f s, write %.2f s), "
                "%llu particles (at most %llu a frame); peak resident memory: importer %.1f MiB, reader %.1f MiB\n",
                r["frames"].get<unsigned long long>(), r["seconds"].get<double>(),
                r["frames_per_second"].get<double>(), r["check_seconds"].get<double>(),
                r["read_seconds"].get<double>(), r["import_seconds"].get<double>(), r["write_seconds"].get<double>(),
                r["particles"].get<unsigned long long>(), r["particles_max"].get<unsigned long long>(),
                r["importer_peak_rss_bytes"].get<double>() / mib, r["reader_peak_rss_bytes"].get<double>() / mib);
  std::printf("importer peak memory, longest run over shortest: %.3f\n", j["peak_rss_ratio"].get<double>());
}

}  // namespace

void add_bench_vdb_sequence_command(CLI::App& bench) {
  struct Args {
    VdbSequenceBenchOptions options;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  VdbSequenceBenchOptions& o = args->options;
  CLI::App* cmd = bench.add_subcommand(
      "vdb-sequence", "An animated VDB sequence imported at several lengths: frames per second, peak memory");
  cmd->add_option("--frames", o.lengths, "Sequence lengths to import (default 25,100)")
      ->delimiter(',')
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--side", o.side, "The puff's cube, voxels a side (default 64)")->check(CLI::Range(8, 512));
  cmd->add_option("--error", o.error, "The import's error target (default 0.03)")->check(CLI::Range(1e-6, 1.0));
  cmd->add_option("--keep", o.keep, "Keep the generated sequence and the imports in this folder");
  cmd->add_flag("--json", args->json, "Print one JSON object");
  cmd->callback([args] {
    args->options.progress = terminal_progress();
    args->options.on_note = [](const std::string& line) {
      std::fprintf(stderr, "pyro bench vdb-sequence: %s\n", line.c_str());
    };
    const nlohmann::json j = bench_vdb_sequence(args->options);
    if (args->json)
      write_stdout(j.dump() + "\n");
    else
      print_vdb_sequence(j);
  });
}

}  // namespace pyro::cli
