#include "systems/runtime/cloud_import/fire_exposure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>

#include "systems/runtime/cloud_import/grid_framing.h"
#include "systems/runtime/cloud_import/scene_volume.h"
#include "systems/runtime/reference/particle_reference.h"

namespace pyro {

namespace {

// Every voxel's emitted radiance, once (the lines visit each voxel six times).
std::vector<glm::vec3> voxel_emission(const DenseGrid& temperature, const TemperatureEmission& emission) {
  std::vector<glm::vec3> le(temperature.size());
  for (size_t i = 0; i < le.size(); ++i) le[i] = emitted_radiance(emission, temperature.values[i]);
  return le;
}

// The median of six views' brightest lines (see fire_exposure.h).
double median_of_six(std::array<double, 6> brightest) {
  std::sort(brightest.begin(), brightest.end());
  return 0.5 * (brightest[2] + brightest[3]);
}

// The brightest of the lines along `axis` seen from its low end and from its high end: the
// radiance leaving a line's end, accumulated from its far end voxel by voxel.
std::array<double, 2> brightest_along_axis(const DenseGrid& density, double extinction, const std::vector<glm::vec3>& le,
                            int axis) {
  const std::array<size_t, 3> stride{1, size_t(density.dims[0]), size_t(density.dims[0]) * density.dims[1]};
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double sigma_step = extinction * glm::length(glm::dvec3(density.index_to_world[axis]));
  const int n = density.dims[axis];
  std::array<double, 2> brightest{0.0, 0.0};
  for (int j = 0; j < density.dims[v]; ++j)
    for (int i = 0; i < density.dims[u]; ++i) {
      const size_t first = i * stride[u] + j * stride[v];
      glm::dvec3 towards_low(0.0), towards_high(0.0);
      for (int k = 0; k < n; ++k) {
        const size_t hi = first + size_t(n - 1 - k) * stride[axis], lo = first + size_t(k) * stride[axis];
        const double keep_hi = std::exp(-sigma_step * std::max(0.0f, density.values[hi]));
        const double keep_lo = std::exp(-sigma_step * std::max(0.0f, density.values[lo]));
        towards_low = towards_low * keep_hi + (1.0 - keep_hi) * glm::dvec3(le[hi]);
        towards_high = towards_high * keep_lo + (1.0 - keep_lo) * glm::dvec3(le[lo]);
      }
      brightest[0] = std::max({brightest[0], towards_low.x, towards_low.y, towards_low.z});
      brightest[1] = std::max({brightest[1], towards_high.x, towards_high.y, towards_high.z});
    }
  return brightest;
}

}  // namespace

double brightest_fire_sightline(const DenseGrid& density, double extinction, const DenseGrid& temperature,
                                const TemperatureEmission& emission) {
  if (density.empty() || temperature.size() != density.size() || emission.table.size == 0) return 0.0;
  const std::vector<glm::vec3> le = voxel_emission(temperature, emission);
  std::array<double, 6> brightest{};
  for (int axis = 0; axis < 3; ++axis) {
    const std::array<double, 2> ends = brightest_along_axis(density, extinction, le, axis);
    brightest[2 * axis] = ends[0];
    brightest[2 * axis + 1] = ends[1];
  }
  return median_of_six(brightest);
}

double exposed_fire_intensity(const DenseGrid& density, double extinction, const DenseGrid& temperature,
                              const TemperatureMapping& mapping) {
  const TemperatureEmission unit = make_temperature_emission(mapping, 1.0, temperature.max_value);
  return exposure_for_sightline(brightest_fire_sightline(density, extinction, temperature, unit));
}

double exposure_for_sightline(double brightest) {
  if (!(brightest > 0.0)) return kDefaultEmissionIntensity;
  return std::min(kMaxExposedIntensity, kFireExposure / brightest);
}

double brightest_particle_sightline(const GridHeader& grid, const std::vector<GaussianParticle>& particles,
                                    int resolution, int threads) {
  const ParticlePool pool = to_particle_pool(particles);
  const std::vector<CameraDescription> views = views_around(grid);
  std::array<double, 6> brightest{};
  for (size_t k = 0; k < views.size() && k < brightest.size(); ++k) {
    const RgbImage image =
        render_particles_reference(pool, camera_frame(views[k], resolution, resolution), glm::dvec3(0.0), threads);
    for (float c : image.rgb) brightest[k] = std::max(brightest[k], double(c));
  }
  return median_of_six(brightest);
}

}  // namespace pyro
