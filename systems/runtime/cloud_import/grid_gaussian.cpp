#include "systems/runtime/cloud_import/grid_gaussian.h"

#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>
#include <glm/matrix.hpp>

#include "engine/math/symmetric_eigen.h"
#include "systems/runtime/reference/volume_reference.h"

namespace pyro {

std::vector<GridGaussian> grid_gaussians_from_particles(const DenseGrid& grid,
                                                        const std::vector<GaussianParticle>& particles,
                                                        const VolumeMedium& medium) {
  const glm::dmat4 to_index = world_to_local_index(grid);
  const glm::dmat3 m(grid.index_to_world);  // world = M index (+ translation)
  const double erf3 = std::erf(3.0 / std::numbers::sqrt2);
  std::vector<GridGaussian> out;
  out.reserve(particles.size());
  for (const GaussianParticle& p : particles) {
    const double s = p.radius / 3.0;
    // Sigma_world = s^2 I, so Sigma_index^-1 = M^T M / s^2 and A = M / s.
    const double tau0 = -std::log1p(-double(p.density));
    const double k = tau0 / (s * std::sqrt(2.0 * std::numbers::pi) * erf3);
    GridGaussian g;
    g.mean = glm::vec3(to_index * glm::dvec4(p.x, p.y, p.z, 1.0));
    g.shape = glm::mat3(m / s);
    g.peak = float(k / medium.extinction);
    out.push_back(g);
  }
  return out;
}

AnisotropicGaussian world_gaussian(const DenseGrid& grid, const GridGaussian& g, double extinction) {
  const glm::dmat3 m(grid.index_to_world);
  const glm::dmat3 a(g.shape);
  const glm::dmat3 cov_index = glm::inverse(glm::transpose(a) * a);
  const SymmetricEigen e = symmetric_eigen(m * cov_index * glm::transpose(m));
  const glm::dvec4 origin(grid.origin[0], grid.origin[1], grid.origin[2], 0.0);
  AnisotropicGaussian w;
  w.centre = glm::vec3(grid.index_to_world * (glm::dvec4(glm::dvec3(g.mean), 1.0) + origin));
  w.rotation = glm::quat(glm::quat_cast(glm::mat3(e.vectors)));
  w.scale = glm::vec3(glm::sqrt(glm::max(e.values, glm::dvec3(0.0))));
  w.extinction = float(extinction * g.peak);
  return w;
}

glm::vec3 grid_gaussian_sigmas(const GridGaussian& g) {
  const glm::dmat3 a(g.shape);
  const SymmetricEigen e = symmetric_eigen(glm::inverse(glm::transpose(a) * a));
  return glm::vec3(glm::sqrt(glm::max(e.values, glm::dvec3(0.0))));
}

}  // namespace pyro
