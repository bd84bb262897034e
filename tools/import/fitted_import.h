#pragma once
// The import that meets an image error target from every side: the octree's isotropic particles
// (systems/runtime/cloud_import/cloud_import.h) start it, their means, shapes and densities are fitted to
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
#include "tools/import/sparse_import_error.h"

#include "tools/import/vdb_import_evaluation.h"

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
// cannot be fitted against the dense reference: it is imported sparse by the octree alone, at the
// error target's tolerance, as isotropic particles, and measured from the seven views around it
// against single scattering path traced through its bricks (sparse_import_error.h), `samples`
// paths per pixel at size x size. The target is met when every view's error, the truth's noise
// taken out, is within it.
struct SparseImport {
  std::vector<GaussianParticle> particles;
  CloudImportReport report;
  VolumeMedium medium;
  double tau_tolerance = 0.0;
  double import_seconds = 0.0;
  std::vector<SparseViewError> views;  // views_around's order
  double measure_seconds = 0.0;
  bool target_met = false;
  std::string reason;  // why the import is not fitted, and why the target is missed
};
SparseImport import_sparse(const SparseGrid& grid, double error, int size, int samples);
// The same fields as fitted_import_summary (rmse: the first view's; rmse_inside null), with
// view_noise (the truth's noise in each view), rmse_views_max_without_noise, measure_seconds and
// reference (what the truth is).
nlohmann::json sparse_import_summary(const SparseImport& import, double error);

}  // namespace pyro
