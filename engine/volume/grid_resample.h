#pragma once
// A second grid of a file (a temperature beside the density) carried into the first grid's index
// space, so that both are indexed alike whatever their transforms and boxes: the value at each
// voxel centre of `target` is the source's trilinear reconstruction at the same world point.
// Outside the source's stored box the source holds its background 0, so values fall linearly to 0
// over the one voxel past its edge (as systems/runtime/reference/grid_sampling.h reconstructs a grid).
// A function that is linear in world space is reproduced exactly wherever the eight source voxels
// around the point are stored.
#include "engine/volume/dense_grid.h"

namespace pyro {

// The resampled grid: `target`'s header (its box and transform), `source`'s name, file and index,
// values from `source`, max_value the largest resampled value (at least 0).
DenseGrid resample_into(const DenseGrid& source, const GridHeader& target);

// The trilinear reconstruction of `grid` at local index coordinates (x, y, z) (0 = the first
// stored voxel's centre), 0 beyond the voxel past the box.
double trilinear_at(const DenseGrid& grid, double x, double y, double z);

}  // namespace pyro
