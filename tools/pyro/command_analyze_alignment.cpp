// pyro analyze projection-error --cx X --cy Y --cz Z --radius R --near N [--interocular I] [--json]
// pyro analyze projection-error --surface NAME|all --out DIR [--radius R] [--near N]
//                               [--interocular I] [--grid K] [--csv-only] [--json]
//
// The billboard alignment error of Johnson & McAllister 2005, section 3, for one billboard or
// as the paper's figures 4-13 (tools/analyze/projection_error.h).
#include <memory>

#include "engine/core/user_error.h"
#include "tools/analyze/projection_error.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

struct ProjectionErrorArgs {
  ProjectionErrorOptions options;
  bool json = false;
  // Which options were given.
  CLI::Option* cx_option = nullptr;
  CLI::Option* cy_option = nullptr;
  CLI::Option* cz_option = nullptr;
  CLI::Option* radius_option = nullptr;
  CLI::Option* near_option = nullptr;
  CLI::Option* surface_option = nullptr;
  CLI::Option* out_option = nullptr;
  CLI::Option* grid_option = nullptr;
  CLI::Option* csv_only_option = nullptr;
};

void run_point(const ProjectionErrorArgs& a) {
  for (CLI::Option* o : {a.cx_option, a.cy_option, a.cz_option, a.radius_option, a.near_option})
    if (o->count() == 0)
      throw UserError("command line", o->get_name(),
                      "one billboard needs --cx, --cy, --cz, --radius and --near (or use "
                      "--surface NAME|all --out DIR for the paper's figures)");
  for (CLI::Option* o : {a.out_option, a.grid_option, a.csv_only_option})
    if (o->count() != 0) throw UserError("command line", o->get_name(), "only goes with --surface");
  write_result(analyze_projection_error(a.options), a.json);
}

void run_surfaces(ProjectionErrorArgs& a) {
  for (CLI::Option* o : {a.cx_option, a.cy_option, a.cz_option})
    if (o->count() != 0)
      throw UserError("command line", o->get_name(),
                      "describes one billboard and cannot be combined with --surface");
  a.options.progress = terminal_progress();
  write_result(write_projection_error_figures(a.options), a.json);
}

}  // namespace

void add_analyze_projection_error_command(CLI::App& analyze) {
  auto a = std::make_shared<ProjectionErrorArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "projection-error",
      "Billboard alignment error (Johnson & McAllister section 3, eqs 8-12): viewplane- against "
      "viewpoint-facing billboards, for one billboard or as the paper's figures 4-13");
  a->cx_option = cmd->add_option("--cx", a->options.cx, "Billboard centre C_x (camera coordinates)");
  a->cy_option = cmd->add_option("--cy", a->options.cy, "Billboard centre C_y");
  a->cz_option =
      cmd->add_option("--cz", a->options.cz, "Billboard centre C_z (< -N: beyond the viewplane)");
  a->radius_option =
      cmd->add_option("--radius", a->options.radius, "Billboard radius r (default 0.4 for --surface)")
          ->check(CLI::NonNegativeNumber);
  a->near_option =
      cmd->add_option("--near", a->options.near, "Viewplane distance N (default 1 for --surface)")
          ->check(CLI::PositiveNumber);
  cmd->add_option("--interocular", a->options.interocular, "Interocular distance I (default 0.065)")
      ->check(CLI::NonNegativeNumber);
  a->surface_option = cmd->add_option("--surface", a->options.surface, "fig4 ... fig13, or all");
  a->out_option = cmd->add_option("--out", a->options.out, "Folder for the CSV and PNG files (--surface)");
  a->grid_option = cmd->add_option("--grid", a->options.grid, "Surface nodes per axis (--surface)")
                       ->check(CLI::Range(3, 1001));
  a->csv_only_option =
      cmd->add_flag("--csv-only", a->options.csv_only, "Write the CSV files only (--surface)");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] {
    if (a->surface_option->count() != 0)
      run_surfaces(*a);
    else
      run_point(*a);
  });
}

}  // namespace pyro::cli
