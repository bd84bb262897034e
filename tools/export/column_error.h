#pragma once
// How far a voxel grid's projection is from its particles': along lines parallel to the grid's
// axes, the column optical depth of the grid as a host reconstructs it (trilinear interpolation
// between voxel centres, so along an axis the integral of a piecewise linear function, voxel
// times the sum of the bilinear lookups in each plane) against the particles' exact column depth
// (their closed forms: engine/math/shadow_caster.h). Reported as optical depth and as what an
// image shows, the column's opacity 1 - exp(-tau): |exp(-tau_grid) - exp(-tau_particles)|, which
// is at most |tau_grid - tau_particles|.
//
// The lines are drawn with a fixed seed: half through a particle (within two of its standard
// deviations of its centre), where the media are densest and the grid's error largest, half
// uniformly across the box's face; `lines` along each axis.
#include <cstdint>
#include <vector>

#include "tools/export/media_sample.h"
#include "tools/export/media_voxels.h"

namespace pyro {

struct ColumnError {
  double opacity_max = 0.0;  // the largest |exp(-tau_grid) - exp(-tau_particles)|
  double opacity_rms = 0.0;
  double depth_max = 0.0;    // the largest |tau_grid - tau_particles|
  double depth_peak = 0.0;   // the largest tau_particles met (for scale)
  int lines = 0;             // measured, all axes together
};

ColumnError measure_column_error(const std::vector<MediaSample>& samples, const MediaVoxels& grid,
                                 int lines_per_axis = 512, uint64_t seed = 1);

}  // namespace pyro
