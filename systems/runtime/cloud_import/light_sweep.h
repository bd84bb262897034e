#pragma once
// Optical depth from every voxel to a directional light in one pass over the grid (the
// slice-by-slice propagation of volume shadow maps; cf. Kniss et al. 2003, "A model for volumetric
// lighting and shadows", half-angle slicing, and Harris & Lastra 2001, whose cloud lighting the
// Johnson paper points to). Slices are taken across the axis along which the light direction (in
// index space) is largest and visited from the light's side. A voxel's depth is the depth at the
// point one slice towards the light (bilinear in that slice) plus the trapezoid rule over the step
// between them. O(voxels of the box), one bilinear lookup each; its error against the marched
// reference (systems/runtime/reference/volume_reference.h, light_optical_depth) is measured in the tests.
//
// Memory: the sweep itself keeps two slices of the box's cross-section (depth and density), so
// it needs no array over the whole box; the dense form returns one, the sparse form returns the
// transmittance of the stored bricks only. Both run the same sweep and give the same floats.
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/volume/sparse_grid.h"

namespace pyro {

// The optical depth at every voxel of the box (same layout as grid.values). threads: 0 for the
// hardware concurrency; the result is the same for every thread count.
std::vector<float> light_optical_depth_sweep(const DenseGrid& grid, const VolumeMedium& medium,
                                             int threads = 0);

// The transmittance to the light, exp(-optical depth), at every voxel of the stored bricks, in the
// layout of grid.values; 1 where the value is 0 (every use of it is weighted by the density) and
// past the box.
std::vector<float> light_transmittance_sweep(const SparseGrid& grid, const VolumeMedium& medium,
                                             int threads = 0);

}  // namespace pyro
