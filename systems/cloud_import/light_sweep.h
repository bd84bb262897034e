#pragma once
// Optical depth from every voxel to a directional light in one pass over the grid (the
// slice-by-slice propagation of volume shadow maps; cf. Kniss et al. 2003, "A model for volumetric
// lighting and shadows", half-angle slicing, and Harris & Lastra 2001, whose cloud lighting the
// Johnson paper points to). Slices are taken across the axis along which the light direction (in
// index space) is largest and visited from the light's side. A voxel's depth is the depth at the
// point one slice towards the light (bilinear in that slice) plus the trapezoid rule over the step
// between them. O(voxels), one bilinear lookup each; its error against the marched reference
// (systems/reference/volume_reference.h, light_optical_depth) is measured in the tests.
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"

namespace pyro {

// threads: 0 for the hardware concurrency; the result is the same for every thread count.
std::vector<float> light_optical_depth_sweep(const DenseGrid& grid, const VolumeMedium& medium,
                                             int threads = 0);

}  // namespace pyro
