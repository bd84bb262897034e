#pragma once
// Density grid -> Gaussian particles whose splatted field reproduces the grid's optical depth.
//
// The model. A lattice of Gaussians of spacing h and standard deviation s = kappa h sums to a
// constant to within 2 exp(-2 pi^2 kappa^2) (Poisson summation; 1.6e-3 for kappa = 0.6), so a
// block of b^3 voxels of mean density m is represented by one Gaussian at its centre whose
// integral equals the block's mass: k = sigma_t_mean * V_block / ((2 pi)^(3/2) s^3), with
// s = kappa * b * voxel length. Its optical depth through the centre (clamped kernel, see
// engine/math/footprint.h) is tau0 = k s sqrt(2 pi) erf(3 / sqrt 2), and the splat's density is
// rho = 1 - exp(-tau0), so the opacity at the centre is exact (systems/runtime/reference/particle_reference.h
// uses the same relation).
//
// Merging (an octree over a mip pyramid). Top blocks are 2^max_level voxels on a side. A block is
// accepted as one particle when the optical depth error it would make is within the target:
// both its internal spread (RMS deviation from its mean) and its step to each face neighbour's
// mean, times the extinction and the block's side length, must be at most `tau_tolerance`;
// otherwise it is split into 8 children. Single voxels are always accepted. Blocks whose whole
// optical depth is below tau_tolerance / 64 are dropped. So the one knob (the CLI's --error)
// decides the particle count: smooth regions become few large particles, detail stays small.
//
// Lighting (Harris & Lastra 2001, single scattering with self-shadowing): the optical depth to the
// light is propagated through the grid (light_sweep.h); a particle's colour is
// albedo * (light * T + ambient), T the density-weighted mean of exp(-tau_light) over its block.
#include <cstdint>
#include <vector>

#include "engine/particles/gaussian_particle.h"
#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/volume/sparse_grid.h"

namespace pyro {

struct CloudImportOptions {
  VolumeMedium medium;
  double tau_tolerance = 0.05;  // optical depth error allowed per block (see above)
  int max_level = 4;            // top blocks are 2^max_level voxels on a side
  double kappa = 0.6;           // Gaussian sigma as a fraction of the block side
  int threads = 0;              // 0: hardware concurrency
};

struct CloudImportReport {
  uint64_t active_voxels = 0;
  uint64_t particles = 0;
  std::vector<uint64_t> particles_per_level;  // index = level (block side 2^level voxels)
  double light_seconds = 0.0;
  double fit_seconds = 0.0;
};

// The grid as Gaussian particles. Memory in proportion to the active voxels: the light sweep keeps
// two slices of the box's cross-section, the transmittance and the pyramid's levels up to blocks
// of 8^3 live in the grid's bricks, coarser levels are dense over the box (1/4096 of it). The
// particles and their order are the same for every thread count.
std::vector<GaussianParticle> import_cloud(const SparseGrid& grid, const CloudImportOptions& options,
                                           CloudImportReport* report = nullptr);
// The same for a dense grid (made sparse first, sparse_from_dense): bit for bit the particles of
// the sparse form of the same grid.
std::vector<GaussianParticle> import_cloud(const DenseGrid& grid, const CloudImportOptions& options,
                                           CloudImportReport* report = nullptr);

// Default extinction for a grid: chosen so that a ray crossing the grid's densest line of
// voxels along its shortest axis sees an optical depth of `target_depth`... in practice
// extinction = target_depth / (max_value * shortest world extent of the active box).
double default_extinction(const GridHeader& grid, double target_depth = 8.0);

// The importer's per-block optical depth tolerance for an image error target E (an RMSE of linear
// colour in [0, 1]). An optical depth error dtau changes a pixel by at most |dtau| times the
// difference between the medium's colour and what lies behind it; the constant was calibrated on
// the Disney cloud and the OpenVDB smoke (docs/vdb_import.md) and the achieved error is
// always measured and reported, never assumed.
double tau_tolerance_for_error(double error);

// The world-space axis-aligned bounds of the grid's index box (voxel centres +- 0.5).
void grid_world_bounds(const GridHeader& grid, glm::dvec3& lo, glm::dvec3& hi);

}  // namespace pyro
