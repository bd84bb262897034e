// pyro chart NAME --out DIR [--width W] [--height H] [--frames N] [--csv-only] [--json]
// One chart per command: time (x) against error (y), one point per setting, the Pareto front
// marked (the scale chart: ms against particles, log-log). The data come from
// tools/charts/chart_<name>.cpp (charts.h); DIR/NAME.csv is written
// atomically, then tools/plots/plot_pareto.py draws DIR/NAME.png from it.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/io_error.h"
#include "engine/io/text_file.h"
#include "tools/charts/charts.h"
#include "tools/pyro/commands.h"
#include "tools/charts/plot_script.h"
#include "tools/pyro/progress.h"
#include "tools/pyro/stdout_text.h"

namespace pyro::cli {

namespace {

namespace fs = std::filesystem;

struct ChartArgs {
  std::string name, out;
  int width = 0, height = 0, frames = 0;  // 0: the chart's default
  bool csv_only = false;
  bool json = false;
};

template <class Options>
void override_size(Options& o, const ChartArgs& a) {
  if (a.width > 0) o.width = a.width;
  if (a.height > 0) o.height = a.height;
}

// An option the chart does not use is a mistake, not something to ignore silently.
void refuse_unused(const ChartArgs& a, bool size_used, bool frames_used) {
  auto refuse = [&](const char* option) {
    throw UserError("command line", option, "not used by the " + a.name + " chart (" +
                                                (size_used ? "it takes --width and --height" : "it has no image size") +
                                                (frames_used ? " and --frames)" : ", no --frames)"));
  };
  if (!size_used && a.width > 0) refuse("--width");
  if (!size_used && a.height > 0) refuse("--height");
  if (!frames_used && a.frames > 0) refuse("--frames");
}

ChartTable make_chart(const ChartArgs& a) {
  const bool renders = a.name == "billboard-modes" || a.name == "layer-resolution" ||
                       a.name == "particle-budget" || a.name == "shadows" ||
                       a.name == "scattering" || a.name == "flipbook-blend";
  refuse_unused(a, renders,
                a.name == "billboard-modes" || a.name == "layer-resolution" || a.name == "shadows" ||
                    a.name == "scattering");
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
  throw UserError("command line", "NAME", "one of footprint, billboard-modes, layer-resolution, "
                                          "particle-budget, integrators, shadows, scattering, flipbook-blend, scale; found \"" + a.name + "\"");
}

// Before any measuring: --out must be a folder or creatable as one, in a folder that can be
// written (a mistake found after minutes of work wastes them).
void check_out_dir(const ChartArgs& a) {
  std::error_code ec;
  if (fs::exists(a.out, ec) && !fs::is_directory(a.out, ec))
    throw UserError(a.out, "--out", "a folder for the chart's files, found a file");
  fs::path existing = fs::absolute(a.out, ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw UserError(a.out, "--out", "a folder path, found a file at \"" + existing.string() + "\"");
  if (::access(existing.c_str(), W_OK) != 0) throw IoError(existing.string(), "write into the folder", errno);
}

void make_out_dir(const ChartArgs& a) {
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec || !fs::is_directory(a.out))
    throw UserError(a.out, "--out", "cannot create the folder: " + ec.message());
}

// The scale chart: its own CSV and plot (charts.h), the benchmark's slopes in the report.
void run_scale_chart(const ChartArgs& a) {
  ScaleChartOptions o;
  override_size(o, a);
  if (a.frames > 0) o.frames = a.frames;
  o.progress = terminal_progress();
  const ScaleChart chart = chart_scale(o);
  make_out_dir(a);
  const fs::path csv = fs::path(a.out) / "scale.csv", png = fs::path(a.out) / "scale.png";
  write_text_file(csv.string(), chart.csv);
  if (!a.csv_only)
    run_plot_script("plot_scale.py", {csv.string(), png.string()}, "; the CSV file is written: " + csv.string());
  nlohmann::json report = {{"chart", "scale"}, {"csv", csv.string()}, {"summary", chart.bench}};
  if (!a.csv_only) report["png"] = png.string();
  if (a.json) {
    write_stdout(report.dump() + "\n");
    return;
  }
  std::printf("scale: cpu slope %s, frame slope %s\n  %s\n", chart.bench["cpu_slope"].dump().c_str(),
              chart.bench["frame_slope"].dump().c_str(), csv.string().c_str());
  if (!a.csv_only) std::printf("  %s\n", png.string().c_str());
}

void run_chart(const ChartArgs& a) {
  check_out_dir(a);
  if (a.name == "scale") {
    run_scale_chart(a);
    return;
  }
  const fs::path out_dir(a.out);
  // Everything is measured (and every mistake found) before anything is written.
  const ChartTable table = make_chart(a);
  make_out_dir(a);
  const fs::path csv = out_dir / (table.name + ".csv");
  const fs::path png = out_dir / (table.name + ".png");
  write_text_file(csv.string(), chart_csv(table));
  if (!a.csv_only)
    run_plot_script("plot_pareto.py", {csv.string(), png.string()},
                    "; the CSV file is written: " + csv.string());
  nlohmann::json points = nlohmann::json::array();
  for (const ChartTable::Row& r : table.rows)
    points.push_back({{"label", r.label}, {"time", r.time}, {"error", r.error}, {"pareto", r.pareto}});
  nlohmann::json report = {{"chart", table.name}, {"csv", csv.string()}, {"points", points},
                           {"summary", table.summary}};
  if (!a.csv_only) report["png"] = png.string();
  if (a.json) {
    write_stdout(report.dump() + "\n");
    return;
  }
  std::printf("%s: %zu points\n  %s\n", table.title.c_str(), table.rows.size(), csv.string().c_str());
  if (!a.csv_only) std::printf("  %s\n", png.string().c_str());
  for (const ChartTable::Row& r : table.rows)
    std::printf("  %-36s %12.4g %-4s %12.4g%s\n", r.label.c_str(), r.time, "", r.error,
                r.pareto ? "  (Pareto front)" : "");
}

}  // namespace

std::vector<std::string> chart_names() {
  return {"footprint",  "billboard-modes", "layer-resolution", "particle-budget",
          "integrators", "shadows",         "scattering",       "flipbook-blend", "scale"};
}

void add_chart_command(CLI::App& app) {
  auto a = std::make_shared<ChartArgs>();
  CLI::App* cmd = app.add_subcommand(
      "chart", "Time against error, one point per setting, Pareto front marked: CSV and PNG");
  cmd->add_option("name", a->name, "footprint, billboard-modes, layer-resolution, particle-budget, integrators, shadows, scattering, flipbook-blend or scale")
      ->required()
      ->check(CLI::IsMember(chart_names()));
  cmd->add_option("--out", a->out, "Folder for NAME.csv and NAME.png")->required();
  cmd->add_option("--width", a->width, "Image width (billboard-modes, layer-resolution, particle-budget, flipbook-blend, scale)")
      ->check(CLI::Range(16, 4096));
  cmd->add_option("--height", a->height, "Image height (billboard-modes, layer-resolution, particle-budget, flipbook-blend, scale)")
      ->check(CLI::Range(16, 4096));
  cmd->add_option("--frames", a->frames, "Timed frames per point (billboard-modes, layer-resolution, scale)")
      ->check(CLI::Range(1, 10000));
  cmd->add_flag("--csv-only", a->csv_only, "Write the CSV only (no matplotlib needed)");
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run_chart(*a); });
}

}  // namespace pyro::cli
