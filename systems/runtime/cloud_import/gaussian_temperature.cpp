#include "systems/runtime/cloud_import/gaussian_temperature.h"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

#include "systems/runtime/reference/parallel_rows.h"

namespace pyro {

namespace {

// The voxels of g's ellipsoid |A (v - mean)| <= 3: its axis-aligned box, clamped to the grid.
struct VoxelBox {
  int lo[3], hi[3];
};

VoxelBox ellipsoid_box(const DenseGrid& grid, const GridGaussian& g) {
  const glm::dmat3 a(g.shape);
  const glm::dmat3 cov = glm::inverse(glm::transpose(a) * a);
  VoxelBox box;
  for (int k = 0; k < 3; ++k) {
    const double half = kAnisotropicExtent * std::sqrt(std::max(cov[k][k], 0.0));
    box.lo[k] = std::max(0, int(std::ceil(g.mean[k] - half)));
    box.hi[k] = std::min(grid.dims[k] - 1, int(std::floor(g.mean[k] + half)));
  }
  return box;
}

float temperature_of(const DenseGrid& density, const DenseGrid& temperature, const GridGaussian& g) {
  const VoxelBox box = ellipsoid_box(density, g);
  double weighted = 0.0, weight = 0.0, profile_weighted = 0.0, profile = 0.0;
  for (int z = box.lo[2]; z <= box.hi[2]; ++z)
    for (int y = box.lo[1]; y <= box.hi[1]; ++y)
      for (int x = box.lo[0]; x <= box.hi[0]; ++x) {
        const glm::vec3 u = g.shape * (glm::vec3(float(x), float(y), float(z)) - g.mean);
        const double m2 = glm::dot(u, u);
        if (m2 > kAnisotropicExtent * kAnisotropicExtent) continue;
        const double p = std::exp(-0.5 * m2), t = temperature.at(x, y, z);
        const double w = p * std::max(0.0f, density.at(x, y, z));
        weighted += w * t;
        weight += w;
        profile_weighted += p * t;
        profile += p;
      }
  if (weight > 0.0) return float(weighted / weight);
  return profile > 0.0 ? float(profile_weighted / profile) : 0.0f;
}

}  // namespace

std::vector<float> gaussian_temperatures(const DenseGrid& density, const DenseGrid& temperature,
                                         const std::vector<GridGaussian>& gaussians, int threads) {
  std::vector<float> out(gaussians.size(), 0.0f);
  if (density.empty() || temperature.values.size() != density.values.size()) return out;
  parallel_rows(int(gaussians.size()), threads,
                [&](int i) { out[size_t(i)] = temperature_of(density, temperature, gaussians[size_t(i)]); });
  return out;
}

void apply_emission(std::vector<AnisotropicGaussian>& particles, const std::vector<float>& temperatures,
                    const TemperatureEmission& emission) {
  for (size_t i = 0; i < particles.size() && i < temperatures.size(); ++i)
    particles[i].emission = emitted_radiance(emission, temperatures[i]);
}

}  // namespace pyro
