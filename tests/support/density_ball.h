#pragma once
// A soft ball of density for volume tests: n^3 voxels, density 1 - (r / radius)^2 inside
// `radius_voxels` of the grid's centre and 0 outside, written as an OpenVDB fog volume.
#include <cmath>
#include <string>
#include <vector>

#include "engine/io/vdb_reader.h"

namespace pyro::test {

inline void write_density_ball(const std::string& path, int n, double radius_voxels, double voxel_size,
                               double origin) {
  std::vector<float> v(size_t(n) * n * n);
  const double c = 0.5 * (n - 1);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double dx = x - c, dy = y - c, dz = z - c;
        const double r = std::sqrt(dx * dx + dy * dy + dz * dz) / radius_voxels;
        v[(size_t(z) * n + y) * n + x] = r < 1.0 ? float(1.0 - r * r) : 0.0f;
      }
  write_vdb_fog_volume(path, "density", {0, 0, 0}, {n, n, n}, v, voxel_size, {origin, origin, origin});
}

}  // namespace pyro::test
