#pragma once
// CPU ground truth for a density grid: emission-absorption ray marching with single scattering
// from a directional light (components/volume_medium.h).
//   (1) light_optical_depth: for every voxel that can influence a sample (those with density, and
//       their neighbours), the optical depth to the light, marched with trilinear sampling.
//   (2) render_volume_reference: per pixel, march the ray through the grid's index box in steps of
//       `step_voxels` index units with the midpoint rule; each step of optical depth dtau adds
//       T * (1 - exp(-dtau)) * S and multiplies T by exp(-dtau) (exact for piecewise-constant
//       sigma_t and S: Max 1995, eq. 8). What is left of T shows the background.
//       The sun's part of S is albedo * light_color * S_sun(mu, tau_light) with `sun`'s phase
//       lobe and octaves (engine/math/scattering_octaves.h); the default is single scattering
//       with an isotropic phase, S_sun = exp(-tau_light). With `emission` (a fire's temperature,
//       volume_emission.h) S gains L_e(T(p)), the emitted radiance of the temperature
//       reconstructed at the sample point (absorption plus emission, Max 1995, eq. 8).
// Rows are spread over std::threads; every pixel is computed independently, so the image does
// not depend on the thread count.
#include <vector>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/math/scattering_octaves.h"
#include "engine/math/camera_math.h"
#include "systems/runtime/reference/rgb_image.h"
#include "systems/runtime/reference/volume_emission.h"

namespace pyro {

// Inverse of the grid's index-to-world map, with the grid origin folded in, so that local index
// coordinates (0 = first stored voxel) come out.
glm::dmat4 world_to_local_index(const GridHeader& grid);

// Optical depth from each voxel centre to the light (dense, same layout as grid.values).
// Voxels whose 3x3x3 neighbourhood has no density get 0 (nothing samples them).
std::vector<float> light_optical_depth(const DenseGrid& grid, const VolumeMedium& medium,
                                       double step_voxels = 0.5, int threads = 0);

struct VolumeRenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;
};

RgbImage render_volume_reference(const DenseGrid& grid, const std::vector<float>& light_depth,
                                 const CameraFrame& camera, const VolumeMedium& medium,
                                 double step_voxels = 0.5, int threads = 0,
                                 VolumeRenderStats* stats = nullptr, const SunScattering& sun = {},
                                 const VolumeEmission* emission = nullptr);

}  // namespace pyro
