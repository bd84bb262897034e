#include "systems/runtime/reference/volume_reference.h"

#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "systems/runtime/reference/grid_sampling.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/pixel_ray.h"

namespace pyro {

glm::dmat4 world_to_local_index(const GridHeader& grid) {
  glm::dmat4 shift(1.0);
  shift[3] = glm::dvec4(-grid.origin[0], -grid.origin[1], -grid.origin[2], 1.0);
  return shift * glm::inverse(grid.index_to_world);
}

std::vector<float> light_optical_depth(const DenseGrid& grid, const VolumeMedium& medium,
                                       double step_voxels, int threads) {
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  std::vector<float> depth(grid.values.size(), 0.0f);
  if (grid.empty()) return depth;
  // Direction towards the light, in local index units per world unit.
  const glm::dmat3 to_index(world_to_local_index(grid));
  const glm::dvec3 d = to_index * -glm::normalize(medium.light_direction);
  const double index_per_world = glm::length(d);
  const glm::dvec3 u = d / index_per_world;  // unit step in index space
  const double world_step = step_voxels / index_per_world;
  const double lo[3] = {-1, -1, -1}, hi[3] = {double(n[0]), double(n[1]), double(n[2])};
  const float* f = grid.values.data();
  const auto has_density_near = [&](int x, int y, int z) {
    for (int k = std::max(z - 1, 0); k <= std::min(z + 1, n[2] - 1); ++k)
      for (int j = std::max(y - 1, 0); j <= std::min(y + 1, n[1] - 1); ++j)
        for (int i = std::max(x - 1, 0); i <= std::min(x + 1, n[0] - 1); ++i)
          if (f[(size_t(k) * n[1] + j) * n[0] + i] > 0.0f) return true;
    return false;
  };
  parallel_rows(n[2] * n[1], threads, [&](int row) {
    const int z = row / n[1], y = row % n[1];
    for (int x = 0; x < n[0]; ++x) {
      if (!has_density_near(x, y, z)) continue;
      const double o[3] = {double(x), double(y), double(z)}, dir[3] = {u.x, u.y, u.z};
      double t0, t1;
      if (!intersect_box(o, dir, lo, hi, t0, t1)) continue;
      double tau = 0.0;
      for (double t = 0.5 * step_voxels; t < t1; t += step_voxels)
        tau += sample_trilinear(f, n, o[0] + t * u.x, o[1] + t * u.y, o[2] + t * u.z);
      depth[(size_t(z) * n[1] + y) * n[0] + x] = float(tau * world_step * medium.extinction);
    }
  });
  return depth;
}

RgbImage render_volume_reference(const DenseGrid& grid, const std::vector<float>& light_depth,
                                 const CameraFrame& camera, const VolumeMedium& medium,
                                 double step_voxels, int threads, VolumeRenderStats* stats,
                                 const SunScattering& sun, const VolumeEmission* emission) {
  const auto start = std::chrono::steady_clock::now();
  RgbImage img;
  img.width = camera.width;
  img.height = camera.height;
  img.rgb.assign(size_t(3) * img.width * img.height, 0.0f);
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  const glm::dmat4 to_local = world_to_local_index(grid);
  const glm::dmat3 to_local3(to_local);
  const glm::dvec3 eye = glm::dvec3(to_local * glm::dvec4(glm::dvec3(camera.eye), 1.0));
  const double lo[3] = {-1, -1, -1}, hi[3] = {double(n[0]), double(n[1]), double(n[2])};
  const float* f = grid.values.data();
  const float* tl = light_depth.data();
  const glm::dvec3 light = glm::normalize(medium.light_direction);
  const float* heat = emission && emission->on() ? emission->temperature.values.data() : nullptr;
  std::vector<uint64_t> samples(img.height, 0);
  parallel_rows(img.height, threads, [&](int y) {
    for (int x = 0; x < img.width; ++x) {
      const glm::dvec3 wd = pixel_ray_direction(camera, x + 0.5, y + 0.5);
      glm::dvec3 L(0.0);
      double T = 1.0;
      const double mu = -glm::dot(light, wd);  // the light's travel against the way to the eye
      if (!grid.empty()) {
        const glm::dvec3 d = to_local3 * wd;  // index units per world unit
        const double ipw = glm::length(d);
        const glm::dvec3 u = d / ipw;
        const double o[3] = {eye.x, eye.y, eye.z}, dir[3] = {u.x, u.y, u.z};
        double t0, t1;
        if (intersect_box(o, dir, lo, hi, t0, t1)) {
          t0 = std::max(t0, 0.0);
          const double dt_world = step_voxels / ipw;
          const int steps = int(std::ceil((t1 - t0) / step_voxels));
          for (int s = 0; s < steps && T > 1e-5; ++s) {
            const double t = t0 + (s + 0.5) * step_voxels;
            const double px = o[0] + t * u.x, py = o[1] + t * u.y, pz = o[2] + t * u.z;
            const float rho = sample_trilinear(f, n, px, py, pz);
            ++samples[y];
            if (rho <= 0.0f) continue;
            const double dtau = medium.extinction * rho * dt_world;
            const double lit = sun_scattering(sun, mu, double(sample_trilinear_clamped(tl, n, px, py, pz)));
            glm::dvec3 S = medium.albedo * (medium.light_color * lit + medium.ambient);
            if (heat) S += glm::dvec3(emitted_radiance(emission->emission, sample_trilinear(heat, n, px, py, pz)));
            const double a = -std::expm1(-dtau);
            L += T * a * S;
            T *= 1.0 - a;
          }
        }
      }
      L += T * medium.background;
      float* p = img.at(x, y);
      p[0] = float(L.x);
      p[1] = float(L.y);
      p[2] = float(L.z);
    }
  });
  if (stats) {
    stats->samples = 0;
    for (uint64_t s : samples) stats->samples += s;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return img;
}

}  // namespace pyro
