#include "tools/import/vdb_file_import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "engine/core/stopwatch.h"
#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_temperature_grid.h"
#include "engine/math/temperature_emission.h"
#include "engine/volume/sparse_grid.h"
#include "systems/runtime/cloud_import/fire_exposure.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "tools/import/fitted_import.h"

namespace pyro {

namespace {

// Writes the particles with their metadata and completes the summary (the import's fields, the
// file's added).
VdbFileImport write_import(const VdbFileImportRequest& a, const GridHeader& grid, ParticleFile pf,
                           nlohmann::json summary, double read_seconds) {
  nlohmann::json meta{{"source", a.file},
                      {"grid", grid.name},
                      {"grid_index", grid.file_index},
                      {"error_target", a.error},
                      {"extinction", summary["extinction"]},
                      {"albedo", summary["albedo"]},
                      {"rmse", summary["rmse"]},
                      {"rmse_views_max", summary["rmse_views_max"]},
                      {"target_met", summary["target_met"]},
                      {"active_voxels", grid.active_voxels}};
  if (summary.contains("temperature") && !summary["temperature"].is_null()) meta["temperature"] = summary["temperature"];
  pf.metadata_json = meta.dump();
  write_particle_file(a.out, pf);
  const double seconds = read_seconds + summary["import_seconds"].get<double>();
  summary.update({{"grid", grid.name}, {"read_seconds", read_seconds}, {"seconds", seconds},
                  {"voxels_per_second", grid.active_voxels / std::max(1e-9, seconds)}, {"out", a.out}});
  return {grid, std::move(summary), seconds};
}

// The temperature grid beside the density (none, or read into the density's index space) and
// the emission the import is measured with: the automatic mapping for its values at the exposed
// intensity (systems/runtime/cloud_import/fire_exposure.h), as a scene shows it unless told otherwise.
struct ImportTemperature {
  std::optional<VdbGridInfo> grid;
  VolumeEmission emission;
  nlohmann::json summary;  // null without a temperature grid
};

ImportTemperature read_import_temperature(const VdbFileImportRequest& a, const DenseGrid& density,
                                          const NoteSink& say) {
  ImportTemperature t;
  t.grid = choose_temperature_grid(a.file, list_vdb_grids(a.file), a.temperature_grid, "--temperature-grid");
  if (!t.grid) {
    say(a.temperature_grid == "none" ? "temperature off (--temperature-grid none)"
                                     : "no temperature grid (looked for \"temperature\", \"heat\", \"flame\"): smoke only");
    return t;
  }
  t.emission.temperature = read_temperature_grid(a.file, *t.grid, density);
  const double top = t.emission.temperature.max_value;
  const TemperatureMapping mapping = automatic_temperature_mapping(top);
  const double intensity =
      exposed_fire_intensity(density, default_medium(density).extinction, t.emission.temperature, mapping);
  t.emission.emission = make_temperature_emission(mapping, intensity, top);
  t.summary = {{"grid", t.grid->name},       {"grid_index", t.grid->index},
               {"max", top},                 {"mapping", automatic_mapping_kind(top)},
               {"scale", mapping.scale},     {"offset", mapping.offset},
               {"intensity", intensity},     {"hottest_kelvin", t.emission.emission.hottest_kelvin}};
  char text[256];
  std::snprintf(text, sizeof text,
                "temperature grid \"%s\" (largest value %g: %s, kelvin = %g value + %g, hottest %.0f K, "
                "exposed at intensity %.3g)",
                t.grid->name.c_str(), top, automatic_mapping_kind(top).c_str(), mapping.scale, mapping.offset,
                t.emission.emission.hottest_kelvin, intensity);
  say(text);
  return t;
}

// A grid too large for a dense box: imported sparse, measured against the path-traced truth.
VdbFileImport import_sparse_file(const VdbFileImportRequest& a, const SparseGrid& sparse,
                                 double read_seconds, const NoteSink& say, ProgressTask& progress) {
  if (!a.temperature_grid.empty() && a.temperature_grid != "none")
    throw UserError(a.file, "--temperature-grid",
                    "a density grid small enough for a dense box to import a temperature beside it; \"" +
                        sparse.name + "\" is imported sparse (use --temperature-grid none)");
  progress.stage(2, "import, and measure against the path-traced truth");
  SparseImport u = import_sparse(sparse, a.error, std::min(a.width, a.height), a.samples);
  say(u.reason);
  progress.finish();
  ParticleFile pf;
  pf.particles = std::move(u.particles);
  return write_import(a, sparse, std::move(pf), sparse_import_summary(u, a.error), read_seconds);
}

}  // namespace

VdbFileImport import_vdb_file(const VdbFileImportRequest& a, const NoteSink& say,
                              ProgressSink* progress_sink) {
  // Stages: read, reference views, import and measure (refined until the target is met).
  ProgressTask progress(progress_sink, "import-vdb " + std::filesystem::path(a.file).filename().string(), 3);
  progress.stage(0, "read");
  const auto t0 = std::chrono::steady_clock::now();
  std::string note;
  const SparseGrid sparse = read_vdb_grid_sparse(a.file, {a.grid, a.grid_index}, &note);
  const double read_seconds = seconds_since(t0);
  if (!note.empty()) say(note);
  if (sparse.converted_from_level_set) say("grid \"" + sparse.name + "\" is a level set; converted to a fog volume");
  if (sparse.empty()) say("grid \"" + sparse.name + "\" has no active voxels; writing 0 particles");
  if (sparse.box_voxels() > kMaxDenseGridVoxels)
    return import_sparse_file(a, sparse, read_seconds, say, progress);
  const DenseGrid grid = dense_from_sparse(sparse);
  ImportTemperature temperature = read_import_temperature(a, grid, say);
  // The image error of what the engine draws against the ground truth, from every side.
  progress.stage(1, "reference views");
  const VdbImportReference reference =
      make_vdb_import_reference(grid, a.width, a.height, true, std::move(temperature.emission));
  progress.stage(2, "import and measure");
  const FittedImport fit = import_to_target(grid, a.error, reference);
  if (!fit.target_met) {
    char text[160];
    std::snprintf(text, sizeof text, "--error %g not met: rmse_views_max %.4f at best (%llu particles, %d refinement(s)); ",
                  a.error, fit.best.rmse_views_max, (unsigned long long)fit.best.report.particles, fit.refinements);
    say(text + fit.reason);
  }
  if (!std::isfinite(fit.best.rmse))
    throw UserError(a.file, "grid \"" + grid.name + "\"", "a grid whose import can be measured, found a non-finite image error");
  progress.update(3);
  progress.finish();
  ParticleFile pf;
  pf.anisotropic = fit.best.fitted;
  pf.temperature = fit.best.temperatures;
  nlohmann::json summary = fitted_import_summary(fit, reference, a.error);
  summary["temperature"] = temperature.summary;
  return write_import(a, grid, std::move(pf), std::move(summary), read_seconds);
}

}  // namespace pyro
