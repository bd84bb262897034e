#pragma once
// The image error of particles imported from a grid too large for a dense box: the particles
// drawn by the GL splats against single scattering path traced through the grid's sparse bricks
// (systems/runtime/reference/path_traced_volume.h), seen from one camera through the import's medium.
// The truth is a Monte Carlo estimate: its noise is reported beside the RMSE, and taken out in
// quadrature (the two are independent, so RMSE² = error² + noise² over the pixels).
#include <vector>

#include "components/volume_medium.h"
#include "engine/particles/gaussian_particle.h"
#include "engine/volume/sparse_grid.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

struct SparseViewError {
  double rmse = 0.0;     // the splats against the path-traced truth
  double noise = 0.0;    // the truth's Monte Carlo error
  double seconds = 0.0;  // the truth's time
  // √max(0, rmse² − noise²): the error of the particles themselves.
  double without_noise() const;
};

SparseViewError sparse_view_error(const SparseGrid& grid, const std::vector<GaussianParticle>& particles,
                                  const VolumeMedium& medium, const CameraDescription& camera, int size,
                                  int samples, int threads);

}  // namespace pyro
