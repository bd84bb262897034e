#pragma once
// A Gaussian in a density grid's local index space (0 = the first stored voxel's centre, one unit
// per voxel), the form in which the importer fits particles to a grid (gaussian_fit.h):
//   rho(x) = peak * exp(-|A (x - mean)|^2 / 2),   Sigma^-1 = A^T A,
// truncated to |A (x - mean)| <= 3 like every particle (engine/particles/anisotropic_gaussian.h).
// A is any invertible 3x3 matrix: A^T A is symmetric positive definite whatever A is, so a
// gradient step can never leave the set of valid shapes. A world particle follows from the grid's
// index-to-world map W (linear part M): centre W(mean), Sigma_world = M Sigma M^T, extinction
// sigma_t * peak.
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "components/volume_medium.h"
#include "engine/io/vdb_reader.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"

namespace pyro {

struct GridGaussian {
  glm::vec3 mean{0.0f};
  glm::mat3 shape{1.0f};  // A
  float peak = 0.0f;      // grid density at the centre
  // The transmittance to the light the Gaussian shows, in [0, 1] (gaussian_lighting.h); its
  // colour is albedo (light lit + ambient).
  float lit = 1.0f;
};

// The octree importer's isotropic particles (cloud_import.h: centre, radius 3 s, opacity at the
// centre rho = 1 - exp(-tau0), tau0 = k s sqrt(2 pi) erf(3 / sqrt 2)) as Gaussians of the grid,
// for the medium they were imported with.
std::vector<GridGaussian> grid_gaussians_from_particles(const DenseGrid& grid,
                                                        const std::vector<GaussianParticle>& particles,
                                                        const VolumeMedium& medium);

// The world particle of one grid Gaussian (colour left white: the lighting is applied apart).
AnisotropicGaussian world_gaussian(const DenseGrid& grid, const GridGaussian& g, double extinction);

// Standard deviations of g along its principal axes in voxels, largest first.
glm::vec3 grid_gaussian_sigmas(const GridGaussian& g);

}  // namespace pyro
