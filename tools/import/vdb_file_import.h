#pragma once
// One OpenVDB file's float grid imported as Gaussian particles, as `pyro import-vdb` does: read
// (sparse), then, for a grid that fits a dense box, imported as anisotropic particles fitted
// until the image error from every side meets the target (fitted_import.h), with the temperature
// grid beside it when there is one; a larger grid imported sparse and measured against the
// path-traced truth. The particle file is written (checked as the loader checks it, durably) only
// then.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "engine/volume/grid_header.h"
#include "systems/runtime/scene_runtime/runtime_options.h"

namespace pyro {

struct VdbFileImportRequest {
  std::string file, grid;  // grid: a name (empty: "density", else the first float grid)
  int grid_index = -1;     // or a position in the file
  std::string temperature_grid;  // empty: the first of kTemperatureGridNames; "none": off
  double error = 0.03;
  int width = 256, height = 256;  // the evaluation images
  int samples = 256;  // the path-traced truth's paths per pixel (grids too large for a dense box)
  std::string out;    // the particle file
};

struct VdbFileImport {
  GridHeader grid;         // the density grid imported
  nlohmann::json summary;  // the import's fields, with grid, read_seconds, seconds, out, ...
  double seconds = 0.0;    // reading and importing
};

// Imports request.file's grid and writes request.out (its destination checked by the caller).
// Notes (conversions, the temperature grid, a target not met) go to `note`; the stages to
// `progress` (may be null).
VdbFileImport import_vdb_file(const VdbFileImportRequest& request, const NoteSink& note,
                              ProgressSink* progress);

}  // namespace pyro
