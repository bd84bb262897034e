#pragma once
// The import's hard cases, made here as grids (no file): a hard-edged box, a thin torus shell, a
// uniform sphere, a noise cloud and a sheet two voxels thick. Each is imported for each error
// target through import-vdb's own refinement (vdb_import_evaluation.h: seven views around it),
// which meets the target or says why it cannot.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/progress_sink.h"
#include "engine/io/vdb_reader.h"

namespace pyro {

struct ImportCase {
  std::string name;
  DenseGrid grid;
};

// The five cases at `scale` (1: the box is 21 voxels a side, 9,261 voxels; the others as large).
std::vector<ImportCase> import_cases(double scale = 1.0);

struct ImportCasesOptions {
  std::vector<double> error_targets{0.03, 0.01};
  int width = 128, height = 128;  // the views' size
  double scale = 1.0;
  ProgressSink* progress = nullptr;
};

// {"width", "height", "cases": [{"name", "active_voxels", "targets": [{"error", "particles",
// "particles_per_voxel", "rmse_views_mean", "rmse_views_max", "rmse_inside", "target_met",
// "refinements", "reason"?}]}]}.
nlohmann::json bench_import_cases(const ImportCasesOptions& options);

}  // namespace pyro
