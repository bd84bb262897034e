// pyro import-vdb FILE [--grid NAME | --grid-index I] [--error E] --out FILE [--json]
//                 [--width W] [--height H]
// Reads one float grid, imports it as anisotropic Gaussian particles fitted to the grid until the
// image error from every side meets the target (systems/benchmarks/fitted_import.h: the splats
// drawn by the real GL renderer, offscreen, against the CPU reference render of the grid from
// seven views around it), and only then writes the particle file (engine/io/particle_file.h: checked as the loader checks it, then
// written durably).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "tools/pyro/commands.h"
#include "tools/pyro/progress.h"
#include "systems/benchmarks/fitted_import.h"

namespace pyro::cli {

namespace {

struct ImportArgs {
  std::string file, grid, out;
  int grid_index = -1;
  double error = 0.03;
  int width = 256, height = 256;
  bool json = false;
  bool list = false;
};

// --list: what the file holds, one grid a line (or a JSON array), nothing written.
void list_grids(const ImportArgs& a) {
  const std::vector<VdbGridInfo> grids = list_vdb_grids(a.file);
  nlohmann::json out = nlohmann::json::array();
  for (const VdbGridInfo& g : grids) {
    out.push_back({{"index", g.index}, {"name", g.name}, {"value_type", g.value_type},
                   {"class", g.grid_class}, {"half_float", g.half_float},
                   {"voxel_size", g.voxel_size}, {"active_voxels", g.active_voxels},
                   {"bbox_min", g.bbox_min}, {"bbox_max", g.bbox_max},
                   {"importable", g.is_float() && g.affine}});
    if (!a.json)
      std::printf("[%d] \"%s\" %s %s%s, %llu active voxels, voxel size %g x %g x %g%s\n", g.index,
                  g.name.c_str(), g.value_type.c_str(), g.grid_class.c_str(),
                  g.half_float ? " (half float)" : "",
                  static_cast<unsigned long long>(g.active_voxels), g.voxel_size[0], g.voxel_size[1],
                  g.voxel_size[2], g.is_float() && g.affine ? "" : "  [cannot be imported]");
  }
  if (a.json) std::printf("%s\n", nlohmann::json{{"file", a.file}, {"grids", out}}.dump().c_str());
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void run_import(const ImportArgs& a) {
  if (a.list) {
    list_grids(a);
    return;
  }
  if (a.out.empty()) throw UserError("command line", "--out", "the particle file to write (.pyrop)");
  if (!(a.error > 0.0 && a.error <= 1.0))
    throw UserError("", "--error", "a number in (0, 1], found " + std::to_string(a.error));
  // Stages: read, reference views, import and measure (refined until the target is met).
  Progress progress("import-vdb " + std::filesystem::path(a.file).filename().string(), 3);
  progress.stage(0, "read");
  const auto t0 = std::chrono::steady_clock::now();
  std::string note;
  const DenseGrid grid = read_vdb_grid(a.file, {a.grid, a.grid_index}, &note);
  const double read_seconds = seconds_since(t0);
  if (!note.empty()) std::fprintf(stderr, "pyro import-vdb: %s: %s\n", a.file.c_str(), note.c_str());
  if (grid.converted_from_level_set)
    std::fprintf(stderr, "pyro import-vdb: %s: grid \"%s\" is a level set; converted to a fog volume\n",
                 a.file.c_str(), grid.name.c_str());
  if (grid.empty())
    std::fprintf(stderr, "pyro import-vdb: %s: grid \"%s\" has no active voxels; writing 0 particles\n",
                 a.file.c_str(), grid.name.c_str());

  // The image error of what the engine draws against the ground truth, from every side.
  progress.stage(1, "reference views");
  const VdbImportReference reference = make_vdb_import_reference(grid, a.width, a.height, true);
  progress.stage(2, "import and measure");
  const FittedImport fit = import_to_target(grid, a.error, reference);
  const VdbImportResult& imported = fit.best;
  if (!fit.target_met)
    std::fprintf(stderr, "pyro import-vdb: %s: --error %g not met: rmse_views_max %.4f at best (%llu particles, %d refinement(s)); %s\n",
                 a.file.c_str(), a.error, imported.rmse_views_max,
                 (unsigned long long)imported.report.particles, fit.refinements, fit.reason.c_str());
  const CloudImportReport& rep = imported.report;
  const double import_seconds = imported.import_seconds;
  const double rmse = imported.rmse;
  if (!std::isfinite(rmse))
    throw UserError(a.file, "grid \"" + grid.name + "\"",
                    "a grid whose import can be measured, found a non-finite image error");
  progress.update(3);
  progress.finish();
  nlohmann::json meta = {{"source", a.file},      {"grid", grid.name},
                         {"grid_index", grid.file_index}, {"error_target", a.error},
                         {"extinction", reference.medium.extinction}, {"rmse", rmse},
                         {"rmse_views_max", imported.rmse_views_max}, {"target_met", fit.target_met},
                         {"active_voxels", rep.active_voxels}};
  ParticleFile pf;
  pf.metadata_json = meta.dump();
  pf.anisotropic = imported.fitted;
  write_particle_file(a.out, pf);

  nlohmann::json summary = {{"active_voxels", rep.active_voxels},
                            {"particles", rep.particles},
                            {"rmse", rmse},
                            {"seconds", read_seconds + import_seconds},
                            {"read_seconds", read_seconds},
                            {"import_seconds", import_seconds},
                            {"light_seconds", rep.light_seconds},
                            {"voxels_per_second", rep.active_voxels / std::max(1e-9, read_seconds + import_seconds)},
                            {"grid", grid.name},
                            {"extinction", reference.medium.extinction},
                            {"tau_tolerance", imported.tau_tolerance},
                            {"error_target", a.error},
                            {"rmse_views_mean", imported.rmse_views_mean},
                            {"rmse_views_max", imported.rmse_views_max},
                            {"view_rmse", imported.view_rmse},
                            {"rmse_inside", std::isfinite(imported.rmse_inside) ? nlohmann::json(imported.rmse_inside)
                                                                               : nlohmann::json(nullptr)},
                            {"views", reference.view_cameras.size()},
                            {"target_met", fit.target_met},
                            {"refinements", fit.refinements},
                            {"out", a.out}};
  if (!fit.target_met) summary["reason"] = fit.reason;
  if (a.json)
    std::printf("%s\n", summary.dump().c_str());
  else
    std::printf("%s: %llu active voxels -> %llu particles, image RMSE over %zu views mean %.4f, max %.4f "
                "(target %g %s), %.3f s; wrote %s\n",
                a.file.c_str(), (unsigned long long)rep.active_voxels,
                (unsigned long long)rep.particles, reference.view_cameras.size(), imported.rmse_views_mean,
                imported.rmse_views_max, a.error, fit.target_met ? "met" : "not met",
                read_seconds + import_seconds, a.out.c_str());
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* cmd = app.add_subcommand("import-vdb", "Import an OpenVDB density grid as Gaussian particles");
  cmd->add_option("file", args->file, "OpenVDB file (.vdb)")->required();
  cmd->add_option("--grid", args->grid, "Grid name (default: \"density\", else the first float grid)");
  cmd->add_option("--grid-index", args->grid_index, "Grid position in the file, from 0 (for repeated names)");
  cmd->add_option("--error", args->error, "Image error target in (0, 1] (default 0.03)");
  cmd->add_option("--out", args->out, "Particle file to write (.pyrop); required unless --list");
  cmd->add_flag("--list", args->list, "List the file's grids (index, name, type, class, voxels) and exit");
  cmd->add_option("--width", args->width, "Width of the evaluation image (default 256)")->check(CLI::Range(1, 8192));
  cmd->add_option("--height", args->height, "Height of the evaluation image (default 256)")->check(CLI::Range(1, 8192));
  cmd->add_flag("--json", args->json, "Print a JSON summary");
  cmd->callback([args] { run_import(*args); });
}

}  // namespace pyro::cli
