#include "tools/pyro/app.h"

#include <string>

#include "engine/gpu/gl_context.h"
#include "engine/gpu/gpu_error.h"
#include "tools/pyro/commands.h"

namespace pyro::cli {

std::string version_text() {
  std::string text = "pyro " PYRO_VERSION "\n";
  try {
    const gpu::HeadlessContext context;
    text += "renderer: " + context.description();
  } catch (const gpu::GpuError& e) {
    text += std::string("renderer: none (no headless OpenGL context could be made: ") + e.what() + ")";
  }
  return text;
}

void add_pyro_commands(CLI::App& app) {
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text,
                       "Print the version and the OpenGL renderer of the headless context, then exit");
  add_render_command(app);
  add_analyze_commands(app);
  add_bench_commands(app);
  add_import_command(app);
  add_export_vdb_command(app);
  add_profile_command(app);
  add_quality_command(app);
  add_view_command(app);
  add_chart_command(app);
  add_schema_command(app);
  add_new_command(app);
  add_farm_command(app);
}

void stop_after_parsing(CLI::App& app) {
  // CLI11 runs the top-level app's parse-complete callback after parsing and before the
  // subcommands' callbacks (App::run_callback).
  app.parse_complete_callback([] { throw ParsedOnly{}; });
}

}  // namespace pyro::cli
