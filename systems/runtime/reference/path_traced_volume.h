#pragma once
// The multiple-scattering ground truth for a density grid: a Monte Carlo path tracer.
// The medium is components/volume_medium.h's: extinction * density per world unit, albedo, a sun
// of irradiance 4π light_color travelling along light_direction (so that single scattering
// matches systems/runtime/reference/volume_reference.h), and a Henyey–Greenstein phase of `anisotropy`.
// A path that leaves the grid after scattering sees a uniform sky of radiance `ambient` (the
// physical counterpart of the ray march's unshadowed ambient term); a camera ray that leaves
// without scattering sees `background`. With max_scattering 1 (single scattering) the collision
// adds albedo x ambient unshadowed instead, as the ray march does: the two estimate the same
// image, the ray march's single-scattering model exactly.
//   - Free paths: delta tracking against the grid's largest density (Woodcock et al. 1965), which
//     samples the true collision density of the trilinear field without bias.
//   - At each collision: next-event estimation of the sun, its transmittance by ratio tracking
//     (Novák, Selle & Jarosz 2014, "Residual ratio tracking for estimating attenuation in
//     participating media": T = Π (1 − σ/σ̄) over the tentative collisions), the weight times
//     the albedo, a new direction from Henyey–Greenstein;
//     Russian roulette keeps the weight at or above 1/4 without bias.
// Each pixel averages `samples_per_pixel` paths through points spread uniformly over the pixel
// (a box filter), and reports the standard error of that mean. Every pixel draws from its own
// random stream (seeded by the pixel and `seed`), so the image does not depend on the threads.
#include <cstdint>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/camera_math.h"
#include "engine/volume/sparse_grid.h"
#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

struct PathTraceOptions {
  int samples_per_pixel = 64;
  int max_scattering = 100000;  // scattering events per path; 1 = single scattering only
  double anisotropy = 0.0;      // Henyey–Greenstein g, (−1, 1)
  uint64_t seed = 1;
  int threads = 0;              // 0: hardware concurrency
};

struct PathTracedImage {
  RgbImage image;
  // The RMS over pixels and channels of each pixel mean's standard error: the RMSE expected
  // between this image and the converged one.
  double monte_carlo_error = 0.0;
  uint64_t paths = 0, scattering_events = 0;
  uint64_t truncated_paths = 0;  // paths stopped by max_scattering while still inside (> 1 only)
  double seconds = 0.0;
};

PathTracedImage path_trace_volume(const DenseGrid& grid, const CameraFrame& camera,
                                  const VolumeMedium& medium, const PathTraceOptions& options);
// The same over a sparse grid's bricks (engine/volume/sparse_grid.h): production-size grids,
// whose dense box would not fit in memory. Its cost follows the optical depth, not the voxels.
PathTracedImage path_trace_volume(const SparseGrid& grid, const CameraFrame& camera,
                                  const VolumeMedium& medium, const PathTraceOptions& options);

}  // namespace pyro
