#include "tools/analyze/projection_error.h"

#include <filesystem>
#include <vector>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"
#include "engine/math/billboard_alignment.h"
#include "tools/charts/plot_script.h"

namespace pyro {

namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestName = "alignment_figures.json";

void draw_charts(const fs::path& manifest, const fs::path& out_dir) {
  cli::run_plot_script("plot_alignment_figures.py", {manifest.string()},
                       "; the CSV files are written in " + out_dir.string());
}

}  // namespace

AnalysisReport analyze_projection_error(const ProjectionErrorOptions& a) {
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
  AnalysisReport r;
  r.json = {{"c_x", a.cx},
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
  r.text += format_text("billboard centre C = (%g, %g, %g), radius r = %g, viewplane N = %g\n",
                        a.cx, a.cy, a.cz, a.radius, a.near);
  r.text += format_text(
      "(camera coordinates, viewpoint at the origin looking down -z; errors are\n"
      " viewplane-facing minus viewpoint-facing, in viewplane units)\n");
  r.text += format_text(
      "                     geometry           paper as printed   corrected closed form\n");
  r.text += format_text("  e_x (eq. 11)      % .9e   % .9e   % .9e\n", geometry.e_x, paper.e_x,
                        closed.e_x);
  r.text += format_text("  e_y (eq. 12)      % .9e   % .9e   % .9e\n", geometry.e_y, paper.e_y,
                        closed.e_y);
  r.text += format_text("parallax error, interocular I = %g (right eye minus left eye):\n",
                        a.interocular);
  r.text += format_text("  horizontal        % .9e   % .9e\n", parallax.horizontal,
                        parallax_paper.horizontal);
  r.text += format_text("  vertical          % .9e   % .9e\n", parallax.vertical,
                        parallax_paper.vertical);
  return r;
}

AnalysisReport write_projection_error_figures(const ProjectionErrorOptions& a) {
  if (a.out.empty())
    throw UserError("command line", "--out", "--surface needs --out DIR, the folder to write to");
  OutputGate().writes({a.out, "--out", OutputShape::container}).check();
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
  ProgressTask progress(a.progress, "analyze projection-error",
                        names.size() + (a.csv_only ? 0 : 1));
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
  AnalysisReport r;
  nlohmann::json& report = r.json;
  report = {{"out", out_dir.string()}, {"figures", nlohmann::json::array()}};
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
  for (const auto& e : report["figures"]) {
    r.text += format_text("%s\n  %s\n", e["title"].get<std::string>().c_str(),
                          e["csv"].get<std::string>().c_str());
    if (e.contains("png")) r.text += format_text("  %s\n", e["png"].get<std::string>().c_str());
  }
  return r;
}

}  // namespace pyro
