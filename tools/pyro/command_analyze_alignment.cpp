// pyro analyze projection-error --cx X --cy Y --cz Z --radius R --near N [--interocular I] [--json]
// pyro analyze projection-error --surface NAME|all --out DIR [--radius R] [--near N]
//                               [--interocular I] [--grid K] [--csv-only] [--json]
//
// The billboard alignment error of Johnson & McAllister 2005, section 3
// (engine/math/billboard_alignment.h, docs/billboard_alignment.md): for one billboard, or as
// the error surfaces of the paper's figures 4-13 written as CSV and drawn as PNG charts by
// tools/plots/plot_alignment_figures.py (Debian's matplotlib, /usr/bin/python3).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/text_file.h"
#include "engine/math/billboard_alignment.h"
#include "tools/charts/alignment_figures.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "tools/charts/external_tool_error.h"
#include "tools/charts/plot_script.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestName = "alignment_figures.json";

struct ProjectionErrorArgs {
  double cx = 0.0, cy = 0.0, cz = 0.0;
  double radius = AlignmentFigureParameters{}.radius;
  double near = AlignmentFigureParameters{}.near;
  double interocular = AlignmentFigureParameters{}.interocular;
  int grid = AlignmentFigureParameters{}.grid;
  std::string surface;
  std::string out;
  bool csv_only = false;
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
  const glm::dvec3 c(a.cx, a.cy, a.cz);
  const std::string why = billboard_alignment_domain_problem(c, a.radius, a.near, a.interocular);
  if (!why.empty()) throw UserError("command line", "--cz", why);

  const ProjectionError geometry = projection_error(c, a.radius, a.near);
  const ProjectionError paper = projection_error_paper(c, a.radius, a.near);
  const ProjectionError closed = projection_error_closed_form(c, a.radius, a.near);
  const ParallaxError parallax = parallax_error(c, a.radius, a.near, a.interocular);
  const ParallaxError parallax_paper = parallax_error_from_translated_surfaces(
      c, a.interocular,
      [&](const glm::dvec3& at) { return projection_error_paper(at, a.radius, a.near); });
  const nlohmann::json out = {{"c_x", a.cx},
                              {"c_y", a.cy},
                              {"c_z", a.cz},
                              {"radius", a.radius},
                              {"near", a.near},
                              {"interocular", a.interocular},
                              {"e_x", geometry.e_x},
                              {"e_y", geometry.e_y},
                              {"e_x_paper", paper.e_x},
                              {"e_y_paper", paper.e_y},
                              {"e_x_closed_form", closed.e_x},
                              {"e_y_closed_form", closed.e_y},
                              {"horizontal_parallax_error", parallax.horizontal},
                              {"vertical_parallax_error", parallax.vertical},
                              {"horizontal_parallax_error_paper", parallax_paper.horizontal},
                              {"vertical_parallax_error_paper", parallax_paper.vertical}};
  if (a.json) {
    write_stdout(out.dump() + "\n");
    return;
  }
  std::printf("billboard centre C = (%g, %g, %g), radius r = %g, viewplane N = %g\n", a.cx, a.cy,
              a.cz, a.radius, a.near);
  std::printf(
      "(camera coordinates, viewpoint at the origin looking down -z; errors are\n"
      " viewplane-facing minus viewpoint-facing, in viewplane units)\n");
  std::printf("                     geometry           paper as printed   corrected closed form\n");
  std::printf("  e_x (eq. 11)      % .9e   % .9e   % .9e\n", geometry.e_x, paper.e_x, closed.e_x);
  std::printf("  e_y (eq. 12)      % .9e   % .9e   % .9e\n", geometry.e_y, paper.e_y, closed.e_y);
  std::printf("parallax error, interocular I = %g (right eye minus left eye):\n", a.interocular);
  std::printf("  horizontal        % .9e   % .9e\n", parallax.horizontal,
              parallax_paper.horizontal);
  std::printf("  vertical          % .9e   % .9e\n", parallax.vertical, parallax_paper.vertical);
}

void draw_charts(const fs::path& manifest, const fs::path& out_dir) {
  run_plot_script("plot_alignment_figures.py", {manifest.string()},
                  "; the CSV files are written in " + out_dir.string());
}

void run_surfaces(const ProjectionErrorArgs& a) {
  for (CLI::Option* o : {a.cx_option, a.cy_option, a.cz_option})
    if (o->count() != 0)
      throw UserError("command line", o->get_name(),
                      "describes one billboard and cannot be combined with --surface");
  if (a.out.empty())
    throw UserError("command line", "--out", "--surface needs --out DIR, the folder to write to");
  std::vector<std::string> names;
  if (a.surface == "all") {
    names = alignment_figure_names();
  } else {
    names.push_back(a.surface);
  }
  AlignmentFigureParameters params;
  params.radius = a.radius;
  params.near = a.near;
  params.interocular = a.interocular;
  params.grid = a.grid;
  // Every figure is computed (and every mistake found) before anything is written.
  std::vector<AlignmentFigure> figures;
  Progress progress("analyze projection-error", names.size() + (a.csv_only ? 0 : 1));
  for (const std::string& name : names) {
    progress.stage(figures.size(), name);
    figures.push_back(make_alignment_figure(name, params));
  }

  const fs::path out_dir(a.out);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir))
    throw UserError(a.out, "--out", "cannot create the folder: " + ec.message());
  nlohmann::json manifest = {{"parameters",
                              {{"radius", params.radius},
                               {"near", params.near},
                               {"interocular", params.interocular},
                               {"grid", params.grid}}},
                             {"figures", nlohmann::json::array()}};
  nlohmann::json report = {{"out", out_dir.string()}, {"figures", nlohmann::json::array()}};
  for (const AlignmentFigure& f : figures) {
    const fs::path csv = out_dir / (f.stem + ".csv");
    write_text_file(csv.string(), alignment_figure_csv(f));
    manifest["figures"].push_back({{"name", f.name},
                                   {"number", f.number},
                                   {"kind", f.kind},
                                   {"title", f.title},
                                   {"csv", f.stem + ".csv"},
                                   {"png", f.stem + ".png"},
                                   {"columns", f.columns},
                                   {"chart", f.chart}});
    nlohmann::json entry = {{"name", f.name}, {"title", f.title}, {"csv", csv.string()}};
    if (!a.csv_only) entry["png"] = (out_dir / (f.stem + ".png")).string();
    report["figures"].push_back(entry);
  }
  const fs::path manifest_path = out_dir / kManifestName;
  write_text_file(manifest_path.string(), manifest.dump(2) + "\n");
  if (!a.csv_only) {
    progress.stage(figures.size(), "charts");
    draw_charts(manifest_path, out_dir);
  }
  progress.update(names.size() + (a.csv_only ? 0 : 1));
  progress.finish();
  report["manifest"] = manifest_path.string();
  report["png"] = !a.csv_only;
  if (a.json) {
    write_stdout(report.dump() + "\n");
    return;
  }
  for (const auto& e : report["figures"]) {
    std::printf("%s\n  %s\n", e["title"].get<std::string>().c_str(),
                e["csv"].get<std::string>().c_str());
    if (e.contains("png")) std::printf("  %s\n", e["png"].get<std::string>().c_str());
  }
}

}  // namespace

void add_analyze_projection_error_command(CLI::App& analyze) {
  auto a = std::make_shared<ProjectionErrorArgs>();
  CLI::App* cmd = analyze.add_subcommand(
      "projection-error",
      "Billboard alignment error (Johnson & McAllister section 3, eqs 8-12): viewplane- against "
      "viewpoint-facing billboards, for one billboard or as the paper's figures 4-13");
  a->cx_option = cmd->add_option("--cx", a->cx, "Billboard centre C_x (camera coordinates)");
  a->cy_option = cmd->add_option("--cy", a->cy, "Billboard centre C_y");
  a->cz_option =
      cmd->add_option("--cz", a->cz, "Billboard centre C_z (< -N: beyond the viewplane)");
  a->radius_option =
      cmd->add_option("--radius", a->radius, "Billboard radius r (default 0.4 for --surface)")
          ->check(CLI::NonNegativeNumber);
  a->near_option =
      cmd->add_option("--near", a->near, "Viewplane distance N (default 1 for --surface)")
          ->check(CLI::PositiveNumber);
  cmd->add_option("--interocular", a->interocular, "Interocular distance I (default 0.065)")
      ->check(CLI::NonNegativeNumber);
  a->surface_option = cmd->add_option("--surface", a->surface, "fig4 ... fig13, or all");
  a->out_option = cmd->add_option("--out", a->out, "Folder for the CSV and PNG files (--surface)");
  a->grid_option = cmd->add_option("--grid", a->grid, "Surface nodes per axis (--surface)")
                       ->check(CLI::Range(3, 1001));
  a->csv_only_option =
      cmd->add_flag("--csv-only", a->csv_only, "Write the CSV files only (--surface)");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] {
    if (a->surface_option->count() != 0)
      run_surfaces(*a);
    else
      run_point(*a);
  });
}

}  // namespace pyro::cli
