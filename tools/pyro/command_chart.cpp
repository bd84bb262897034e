// pyro chart NAME --out DIR [--width W] [--height H] [--frames N] [--density] [--csv-only] [--json]
// One chart per command: time (x) against error (y), one point per setting, the Pareto front
// marked (the scale chart: ms against particles, log-log). The data come from
// tools/charts/chart_<name>.cpp (charts.h), written and drawn by tools/charts/chart_run.h.
#include <memory>

#include "tools/charts/chart_run.h"
#include "tools/charts/charts.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ChartArgs {
  ChartRunOptions options;
  bool json = false;
};

}  // namespace

void add_chart_command(CLI::App& app) {
  auto a = std::make_shared<ChartArgs>();
  CLI::App* cmd = app.add_subcommand(
      "chart", "Time against error, one point per setting, Pareto front marked: CSV and PNG");
  cmd->add_option("name", a->options.name, "footprint, billboard-modes, layer-resolution, particle-budget, integrators, shadows, scattering, flipbook-blend or scale")
      ->required()
      ->check(CLI::IsMember(chart_names()));
  cmd->add_option("--out", a->options.out, "Folder for NAME.csv and NAME.png")->required();
  cmd->add_option("--width", a->options.width, "Image width (billboard-modes, layer-resolution, particle-budget, flipbook-blend, scale)")
      ->check(CLI::Range(16, 4096));
  cmd->add_option("--height", a->options.height, "Image height (billboard-modes, layer-resolution, particle-budget, flipbook-blend, scale)")
      ->check(CLI::Range(16, 4096));
  cmd->add_option("--frames", a->options.frames, "Timed frames per point (billboard-modes, layer-resolution, scale)")
      ->check(CLI::Range(1, 10000));
  cmd->add_flag("--density", a->options.density,
                "shadows: each method on a cumulus that thickens, error against the particles' optical depth");
  cmd->add_flag("--csv-only", a->options.csv_only, "Write the CSV only (no matplotlib needed)");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] {
    a->options.progress = terminal_progress();
    write_result(run_chart(a->options), a->json);
  });
}

}  // namespace pyro::cli
