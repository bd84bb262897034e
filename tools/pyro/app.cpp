#include "tools/pyro/app.h"

#include "tools/pyro/commands.h"

namespace pyro::cli {

void add_pyro_commands(CLI::App& app) {
  app.require_subcommand(1);
  add_render_command(app);
  add_analyze_commands(app);
  add_bench_commands(app);
  add_import_command(app);
  add_profile_command(app);
  add_quality_command(app);
  add_view_command(app);
  add_chart_command(app);
}

void stop_after_parsing(CLI::App& app) {
  // CLI11 runs the top-level app's parse-complete callback after parsing and before the
  // subcommands' callbacks (App::run_callback).
  app.parse_complete_callback([] { throw ParsedOnly{}; });
}

}  // namespace pyro::cli
