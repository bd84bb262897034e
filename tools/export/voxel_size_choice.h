#pragma once
// The voxel size a frame's media are exported at: the largest (fewest voxels) whose grid projects
// within `error` of the particles (column_error.h: the largest column opacity difference over the
// measured lines), found by measuring. Trilinear reconstruction of a smooth field errs by
// about h^2 / 8 times its second derivative (the linear interpolation bound, e.g. Burden & Faires,
// "Numerical Analysis", thm 3.3), so a Gaussian of standard deviation s needs h a fraction of s
// and the error falls as h^2: the search starts at the finest particle's standard deviation and
// rescales h by sqrt(error / measured) (times 0.9, so as to land inside the target), keeping the
// largest size measured within it. A grid over `max_voxels` is never made: the size is then
// refused (VoxelSizeChoice::fits false) with the finest size that fits.
#include <cstdint>
#include <vector>

#include "tools/export/column_error.h"
#include "tools/export/media_sample.h"

namespace pyro {

struct VoxelSizeChoice {
  double voxel = 0.0;      // the size chosen (or, when !fits, the finest whose grid fits)
  ColumnError error;       // measured at that size
  uint64_t voxels = 0;     // its box's voxels
  int tries = 0;           // sizes measured
  bool met = false;        // error.opacity_max <= the target
  bool fits = true;        // false: the target needs a grid over max_voxels
};

VoxelSizeChoice choose_voxel_size(const std::vector<MediaSample>& samples, double error, uint64_t max_voxels,
                                  int max_tries = 8);

// The finest length of the media: the smallest MediaSample::detail.
double finest_detail(const std::vector<MediaSample>& samples);

}  // namespace pyro
