#pragma once
// The import that meets an image error target from every side: the octree's isotropic particles
// (systems/cloud_import/cloud_import.h) start it, their means, shapes and densities are fitted to
// the grid as anisotropic Gaussians (gaussian_fit.h), and while the largest error over the views
// around the grid (vdb_import_evaluation.h, measured with the anisotropic splats against the CPU
// reference of the grid) is above the target, the Gaussians that carry the most residual are
// split and the fit goes on (densify and prune). A start stops when the target is met, when the
// error stops falling (two rounds without a 2 % gain), when there are as many particles as voxels
// or when the rounds run out; a start that misses is followed by a finer one (the octree's
// tolerance halved), up to `starts` of them. The first start that meets the target is kept, else
// the lowest error reached, with the reason its start gave.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/volume/sparse_grid.h"

#include "systems/benchmarks/vdb_import_evaluation.h"

namespace pyro {

struct FitSchedule {
  // The first start's octree is at this multiple of tau_tolerance_for_error(error): coarse, so
  // that the splits go where the error is rather than where the octree's rule put them.
  double start_factor = 4.0;
  int starts = 3;
  int first_steps = 60;         // fit steps before the first measurement
  int round_steps = 30;         // fit steps after each split
  double split_fraction = 0.1;  // of the Gaussians, split each round
  int max_rounds = 12;          // per start
  int threads = 0;
};

struct FittedImport {
  VdbImportResult best;  // the lowest rmse_views_max reached (the first that meets the target)
  bool target_met = false;
  int refinements = 0;  // rounds of split and fit, and finer starts, after the first fit
  std::string reason;   // why the target was not met (empty when it was)
};

FittedImport import_to_target(const DenseGrid& grid, double error, const VdbImportReference& reference,
                              const FitSchedule& schedule = {});

// What import-vdb reports of a fitted import (its --json fields but the command's own: read
// time, output): active_voxels, particles, rmse, import_seconds, light_seconds, extinction,
// tau_tolerance, error_target, rmse_views_mean, rmse_views_max, view_rmse, rmse_inside (null
// without that view), views, target_met, refinements, measured (true), and reason when missed.
nlohmann::json fitted_import_summary(const FittedImport& fit, const VdbImportReference& reference, double error);

// A grid whose box is too large to be made dense (engine/io/vdb_reader.h, kMaxDenseGridVoxels)
// cannot be fitted or measured against the dense reference: it is imported sparse by the octree
// alone, at the error target's tolerance, as isotropic particles.
struct UnmeasuredImport {
  std::vector<GaussianParticle> particles;
  CloudImportReport report;
  VolumeMedium medium;
  double tau_tolerance = 0.0;
  double import_seconds = 0.0;
  std::string reason;  // why the error is not measured
};
UnmeasuredImport import_unmeasured(const SparseGrid& grid, double error);
// The same fields as fitted_import_summary where they apply; the errors and target_met are null,
// measured false, reason said.
nlohmann::json unmeasured_import_summary(const UnmeasuredImport& import, double error);

}  // namespace pyro
