#pragma once
// Lighting fitted Gaussians (gaussian_fit.h) as the octree's particles are lit (cloud_import.h:
// single scattering with self-shadowing, Harris & Lastra 2001), but fitted rather than averaged.
// The grid's emission is rho(x) S(x) with S = albedo (light T(x) + ambient), T the transmittance
// to the light (light_sweep.h); the Gaussians' is sum_i peak_i e_i(x) S_i with S_i = albedo
// (light lit_i + ambient). Both are affine in T, so each Gaussian's `lit` is fitted to the lit
// density rho T by least squares:
//   minimise 1/2 sum_x (sum_i peak_i e_i(x) lit_i - rho(x) T(x))^2,  0 <= lit_i <= 1,
// by simultaneous iterative reconstruction (SIRT; Gilbert 1972, "Iterative methods for the
// three-dimensional reconstruction of an object from projections"): each step moves lit_i by
// -sum_x peak_i e_i r / sum_x peak_i e_i f, f the Gaussians' density sum, which converges for
// non-negative weights, then clamps it. Where Gaussians overlap, their lit values share the
// light's fall-off between them (a dense cloud's bright rim and dark core), which the density-
// weighted mean of T over each Gaussian smears.
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"

namespace pyro {

// T(x) = exp(-tau_light(x)) at every voxel of the grid with density (1 elsewhere), from the
// optical depths to the light in the layout of grid.values (light_sweep.h, or the reference's
// marched ones, systems/runtime/reference/volume_reference.h).
std::vector<float> light_transmittance_field(const DenseGrid& grid, std::vector<float> light_depth);

// Sets every Gaussian's `lit`: the density-weighted mean of T over it, then `iterations` SIRT
// steps of the least-squares fit above. Returns the RMSE of the lit density over the active voxels.
double fit_lit_fractions(const DenseGrid& grid, std::vector<GridGaussian>& gaussians,
                         const std::vector<float>& transmittance, int iterations = 20, int threads = 0);

// Each Gaussian's share of the squared residual of the lit density (as residual_shares).
std::vector<double> lit_residual_shares(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians,
                                        const std::vector<float>& transmittance, int threads = 0);

// The world particles, coloured albedo (light lit + ambient).
std::vector<AnisotropicGaussian> lit_world_gaussians(const DenseGrid& grid, const std::vector<GridGaussian>& gaussians,
                                                     const VolumeMedium& medium);

}  // namespace pyro
