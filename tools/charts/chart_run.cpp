#include "tools/charts/chart_run.h"

#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "engine/core/format_text.h"
#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/output_gate.h"
#include "engine/io/text_file.h"
#include "tools/charts/charts.h"
#include "tools/charts/plot_script.h"

namespace pyro {

using cli::run_plot_script;

namespace {

namespace fs = std::filesystem;

template <class Options>
void override_size(Options& o, const ChartRunOptions& a) {
  if (a.width > 0) o.width = a.width;
  if (a.height > 0) o.height = a.height;
}

// An option the chart does not use is a mistake, not something to ignore silently.
void refuse_unused(const ChartRunOptions& a, bool size_used, bool frames_used) {
  auto refuse = [&](const char* option) {
    throw UserError("command line", option,
                    "not used by the " + a.name + " chart (" +
                        (size_used ? "it takes --width and --height" : "it has no image size") +
                        (frames_used ? " and --frames)" : ", no --frames)"));
  };
  if (!size_used && a.width > 0) refuse("--width");
  if (!size_used && a.height > 0) refuse("--height");
  if (!frames_used && a.frames > 0) refuse("--frames");
}

ChartTable make_chart(const ChartRunOptions& a) {
  const bool renders = a.name == "billboard-modes" || a.name == "layer-resolution" ||
                       a.name == "particle-budget" || a.name == "shadows" ||
                       a.name == "scattering" || a.name == "flipbook-blend";
  refuse_unused(a, renders,
                a.name == "billboard-modes" || a.name == "layer-resolution" ||
                    a.name == "shadows" || a.name == "scattering");
  if (a.density && a.name != "shadows")
    throw UserError("command line", "--density", "only the shadows chart has it, not the " + a.name + " chart");
  if (a.name == "footprint") return chart_footprint({});
  if (a.name == "integrators") return chart_integrators({});
  if (a.name == "billboard-modes") {
    BillboardModesChartOptions o;
    override_size(o, a);
    if (a.frames > 0) o.frames = a.frames;
    return chart_billboard_modes(o);
  }
  if (a.name == "layer-resolution") {
    LayerResolutionChartOptions o;
    override_size(o, a);
    if (a.frames > 0) o.frames = a.frames;
    return chart_layer_resolution(o);
  }
  if (a.name == "shadows" && a.density) {
    ShadowDensityChartOptions o;
    override_size(o, a);
    if (a.frames > 0) o.frames = a.frames;
    return chart_shadow_density(o);
  }
  if (a.name == "shadows") {
    ShadowsChartOptions o;
    override_size(o, a);
    if (a.frames > 0) o.frames = a.frames;
    return chart_shadows(o);
  }
  if (a.name == "scattering") {
    ScatteringChartOptions o;
    override_size(o, a);
    if (a.frames > 0) o.frames = a.frames;
    return chart_scattering(o);
  }
  if (a.name == "flipbook-blend") {
    FlipbookBlendChartOptions o;
    override_size(o, a);
    return chart_flipbook_blend(o);
  }
  if (a.name == "particle-budget") {
    ParticleBudgetChartOptions o;
    override_size(o, a);
    return chart_particle_budget(o);
  }
  throw UserError(
      "command line", "NAME",
      "one of footprint, billboard-modes, layer-resolution, "
      "particle-budget, integrators, shadows, scattering, flipbook-blend, scale; found \"" +
          a.name + "\"");
}

// Before any measuring, --out and the chart's two files pass the gate (engine/io/output_gate.h):
// a mistake found after minutes of work wastes them.
void check_out_dir(const ChartRunOptions& a) {
  OutputGate()
      .writes({a.out, "--out", OutputShape::container})
      .writes_file((fs::path(a.out) / (a.name + ".csv")).string(), "--out")
      .writes_file(a.csv_only ? "" : (fs::path(a.out) / (a.name + ".png")).string(), "--out")
      .check();
}

void make_out_dir(const ChartRunOptions& a) {
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec || !fs::is_directory(a.out))
    throw UserError(a.out, "--out", "cannot create the folder: " + ec.message());
}

// The scale chart: its own CSV and plot (charts.h), the benchmark's slopes in the report.
ChartReport run_scale_chart(const ChartRunOptions& a) {
  ScaleChartOptions o;
  override_size(o, a);
  if (a.frames > 0) o.frames = a.frames;
  o.progress = a.progress;
  const ScaleChart chart = chart_scale(o);
  make_out_dir(a);
  const fs::path csv = fs::path(a.out) / "scale.csv", png = fs::path(a.out) / "scale.png";
  write_text_file(csv.string(), chart.csv);
  if (!a.csv_only)
    run_plot_script("plot_scale.py", {csv.string(), png.string()},
                    "; the CSV file is written: " + csv.string());
  ChartReport r;
  nlohmann::json& report = r.json;
  report = {{"chart", "scale"}, {"csv", csv.string()}, {"summary", chart.bench}};
  if (!a.csv_only) report["png"] = png.string();
  r.text = format_text("scale: cpu slope %s, frame slope %s\n  %s\n",
                       chart.bench["cpu_slope"].dump().c_str(),
                       chart.bench["frame_slope"].dump().c_str(), csv.string().c_str());
  if (!a.csv_only) r.text += format_text("  %s\n", png.string().c_str());
  return r;
}

}  // namespace

ChartReport run_chart(const ChartRunOptions& a) {
  check_out_dir(a);
  if (a.name == "scale") return run_scale_chart(a);
  const fs::path out_dir(a.out);
  // Everything is measured (and every mistake found) before anything is written.
  const ChartTable table = make_chart(a);
  make_out_dir(a);
  const fs::path csv = out_dir / (table.name + ".csv");
  const fs::path png = out_dir / (table.name + ".png");
  write_text_file(csv.string(), chart_csv(table));
  if (!a.csv_only)
    run_plot_script(a.density ? "plot_density.py" : "plot_pareto.py", {csv.string(), png.string()},
                    "; the CSV file is written: " + csv.string());
  nlohmann::json points = nlohmann::json::array();
  for (const ChartTable::Row& row : table.rows)
    points.push_back(
        {{"label", row.label}, {"time", row.time}, {"error", row.error}, {"pareto", row.pareto}});
  ChartReport r;
  nlohmann::json& report = r.json;
  report = {
      {"chart", table.name}, {"csv", csv.string()}, {"points", points}, {"summary", table.summary}};
  if (!a.csv_only) report["png"] = png.string();
  r.text = format_text("%s: %zu points\n  %s\n", table.title.c_str(), table.rows.size(),
                       csv.string().c_str());
  if (!a.csv_only) r.text += format_text("  %s\n", png.string().c_str());
  for (const ChartTable::Row& row : table.rows)
    r.text += format_text("  %-36s %12.4g %-4s %12.4g%s\n", row.label.c_str(), row.time, "",
                          row.error, row.pareto ? "  (Pareto front)" : "");
  return r;
}

std::vector<std::string> chart_names() {
  return {"footprint",       "billboard-modes", "layer-resolution",
          "particle-budget", "integrators",     "shadows",
          "scattering",      "flipbook-blend",  "scale"};
}

}  // namespace pyro
