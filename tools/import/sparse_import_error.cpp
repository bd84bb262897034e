#include "tools/import/sparse_import_error.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "tools/import/relit_particles.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/reference/path_traced_volume.h"
#include "systems/runtime/reference/world_snapshot.h"

namespace pyro {

double SparseViewError::without_noise() const { return std::sqrt(std::max(0.0, rmse * rmse - noise * noise)); }

SparseViewError sparse_view_error(const SparseGrid& grid, const std::vector<GaussianParticle>& particles,
                                  const VolumeMedium& medium, const CameraDescription& camera, int size,
                                  int samples, int threads) {
  SceneRuntime splats = relit_particles_runtime(particles, medium, {camera, size, size, true}, std::nullopt);
  splats.draw_frame(0);
  PathTraceOptions trace;
  trace.samples_per_pixel = samples;
  trace.max_scattering = 1;
  trace.threads = threads;
  const PathTracedImage truth = path_trace_volume(grid, camera_frame(camera, size, size), medium, trace);
  return {image_rmse(rgb_of(splats.image()), truth.image), truth.monte_carlo_error, truth.seconds};
}

}  // namespace pyro
