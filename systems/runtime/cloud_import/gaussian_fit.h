#pragma once
// Fitting anisotropic Gaussians to a density grid: the octree's particles (cloud_import.h) are
// the start; their means, shapes and peaks are then optimised so that the sum of the Gaussians
// matches the grid. This is 3D Gaussian splatting's optimisation and densify-and-prune (Kerbl,
// Kopanas, Leimkuehler & Drettakis 2023, "3D Gaussian Splatting for Real-Time Radiance Field
// Rendering", sections 5 and 5.2) applied to a known volume instead of photographs: the loss is
// taken on the density field itself, so no image is rendered inside the loop.
//
// The loss. E = 1/2 sum_x (f(x) - rho(x))^2 over every voxel centre x of the grid's box and a
// margin of `margin` voxels around it (where rho = 0, so that nothing leaks out), f the sum of the
// Gaussians (grid_gaussian.h: truncated at 3 standard deviations). With u = x - mean, v = A u,
// e = exp(-|v|^2 / 2) and r = f - rho, a Gaussian's gradients are
//   dE/dmean = sum r peak e A^T v,   dE/dA = -sum r peak e v u^T,   dE/d(ln peak) = sum r peak e,
// taken with Adam (Kingma & Ba 2015) on (mean, A, ln peak).
//
// The work is split so that the result does not depend on the thread count: f is summed plane by
// plane (each z plane adds its Gaussians in index order), and each Gaussian gathers its own
// gradient from the residual. Along a row of voxels |v|^2 is a quadratic in x, so only the voxels
// inside the truncation ellipsoid are visited.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"

namespace pyro {

struct GaussianFitOptions {
  int steps = 60;               // Adam steps
  float mean_step = 0.05f;      // Adam step of a mean, in voxels
  float shape_step = 0.02f;     // Adam step of A, relative to A's size at the start
  float peak_step = 0.03f;      // Adam step of ln peak
  float min_sigma = 0.3f;       // no axis thinner than this many voxels
  float max_sigma = 64.0f;      // nor wider
  float max_aspect = 8.0f;      // nor wider than this many times the thinnest axis
  int margin = 3;               // voxels of empty space fitted around the box
  int threads = 0;              // 0: hardware concurrency
};

struct GaussianFitReport {
  double rmse_before = 0.0;  // field RMSE over the active voxels, in the grid's density units
  double rmse_after = 0.0;
  int steps = 0;
  double seconds = 0.0;
};

// Optimises `gaussians` in place.
GaussianFitReport fit_grid_gaussians(const DenseGrid& grid, std::vector<GridGaussian>& gaussians,
                                     const GaussianFitOptions& options = {});

// The loss E above over the box grown by `margin`, and Gaussian i's gradient as the fit takes it:
// d/dmean (3), d/dA column by column (9), d/d(ln peak) (1). For tests against finite differences.
double grid_gaussian_loss(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians, int margin);
std::array<float, 13> grid_gaussian_gradient(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians,
                                             size_t i, int margin);

// The field RMSE of the Gaussians against the grid over its active voxels (those != 0).
double grid_gaussian_rmse(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians, int threads = 0);

// Each Gaussian's share of the squared residual of the density: the sum over its voxels (the
// grid's box grown by `margin`) of (what it adds there / the Gaussians' sum there) r^2.
std::vector<double> residual_shares(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians,
                                    int margin, int threads = 0);

struct DensifyReport {
  uint64_t split = 0, pruned = 0;
};

// Densify and prune: the `split_fraction` of the Gaussians whose `share` of the error is largest
// (residual_shares, and the lighting's, gaussian_lighting.h) are each replaced by two along their
// longest axis (moment-preserving: offsets of +-sigma/2, that axis's sigma times sqrt(3)/2, half
// the mass each), when that axis is wider than 2 min_sigma; Gaussians whose largest optical depth
// (peak * sqrt(2 pi) * longest sigma, times `depth_per_density_voxel`, the extinction times a
// voxel's length) is below `prune_depth` are removed.
DensifyReport densify_and_prune(std::vector<GridGaussian>& gaussians, const std::vector<double>& share,
                                double split_fraction, double depth_per_density_voxel, double prune_depth,
                                const GaussianFitOptions& options = {});

}  // namespace pyro
