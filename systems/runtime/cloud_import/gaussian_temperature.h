#pragma once
// The temperature each imported particle carries, and the emission a scene makes of it.
//
// A particle i of the grid's density is a Gaussian g_i (grid_gaussian.h); the medium it stands for
// emits sigma_t L_e(T) (engine/math/temperature_emission.h). Its temperature is the mean of the
// temperature grid T over the particle's support, weighted by the particle's own density there
// times the grid's density:
//   T_i = sum_v g_i(v) rho(v) T(v) / sum_v g_i(v) rho(v)   over the voxel centres v with m <= 3.
// The weight is where the particle's extinction, and so its emission, is: the grid's density
// keeps the particle's tail in empty air (whose temperature is the grid's background) from
// cooling it, and the particle's profile keeps a neighbour's flame from heating it. The file
// stores T_i in the grid's own units (docs/particle_format.md), and a scene maps it to kelvin.
// A particle with no density under it takes the profile-weighted mean alone (0 with none).
#include <vector>

#include "engine/math/temperature_emission.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/volume/dense_grid.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"

namespace pyro {

// T_i for every Gaussian of `density`, `temperature` being already in density's index space
// (engine/volume/grid_resample.h). The same for every thread count (each Gaussian alone).
std::vector<float> gaussian_temperatures(const DenseGrid& density, const DenseGrid& temperature,
                                         const std::vector<GridGaussian>& gaussians, int threads = 0);

// Each particle's emission: emitted_radiance(emission, temperatures[i]).
void apply_emission(std::vector<AnisotropicGaussian>& particles, const std::vector<float>& temperatures,
                    const TemperatureEmission& emission);

}  // namespace pyro
