#include "engine/volume/procedural_cloud.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/rng.h"

namespace pyro {

namespace {

// A value in [0, 1) for lattice point (x, y, z) of octave o: a hash of the seed and the point.
double lattice(uint64_t seed, int o, int x, int y, int z) {
  uint64_t s = mix_seeds(seed, (uint64_t(uint32_t(x)) << 32) ^ uint64_t(uint32_t(y)) * 0x9E3779B1ull ^
                                   (uint64_t(uint32_t(z)) << 16) ^ (uint64_t(o) << 58));
  return double(splitmix64(s) >> 11) * 0x1.0p-53;
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

// Trilinear value noise at p (lattice units), in [0, 1).
double value_noise(uint64_t seed, int octave, double px, double py, double pz) {
  const int x0 = int(std::floor(px)), y0 = int(std::floor(py)), z0 = int(std::floor(pz));
  const double tx = smooth(px - x0), ty = smooth(py - y0), tz = smooth(pz - z0);
  double v = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz);
    v += w * lattice(seed, octave, x0 + dx, y0 + dy, z0 + dz);
  }
  return v;
}

// Fractal sum of 4 octaves, in [0, 1).
double fbm(uint64_t seed, double x, double y, double z) {
  double sum = 0.0, amplitude = 0.5, norm = 0.0, f = 1.0;
  for (int o = 0; o < 4; ++o) {
    sum += amplitude * value_noise(seed, o, x * f, y * f, z * f);
    norm += amplitude;
    amplitude *= 0.5;
    f *= 2.0;
  }
  return sum / norm;
}

}  // namespace

DenseGrid make_procedural_cloud(const ProceduralCloudOptions& opt) {
  const int nx = std::max(8, opt.width), ny = std::max(4, nx * 3 / 5), nz = std::max(4, nx * 2 / 3);
  DenseGrid g;
  g.name = "density";
  g.dims = {nx, ny, nz};
  g.origin = {0, 0, 0};
  g.voxel_size = {opt.voxel_size, opt.voxel_size, opt.voxel_size};
  g.index_to_world = glm::dmat4(opt.voxel_size);
  g.index_to_world[3] = glm::dvec4(-0.5 * (nx - 1) * opt.voxel_size, -0.5 * (ny - 1) * opt.voxel_size,
                                   -0.5 * (nz - 1) * opt.voxel_size, 1.0);
  g.values.assign(size_t(nx) * ny * nz, 0.0f);

  // Puffs in normalised coordinates (one scale on every axis: x in [-1, 1], y in [-3/5, 3/5],
  // z in [-2/3, 2/3]): a row along x, taller in the middle, bottoms near the flat base.
  struct Puff {
    double x, y, z, r;
  };
  std::vector<Puff> puffs;
  Rng rng(opt.seed);
  const int n = std::max(1, opt.puffs);
  const double floor_y = -0.38;  // the flat base
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : -0.55 + 1.1 * i / (n - 1);  // along the long axis
    const double centre_weight = 1.0 - t * t;                    // taller in the middle
    Puff p;
    p.x = t + 0.12 * (rng.uniform() - 0.5);
    p.z = 0.2 * (rng.uniform() - 0.5);
    p.r = 0.14 + 0.22 * centre_weight + 0.05 * rng.uniform();
    p.y = floor_y + 0.8 * p.r + 0.06 * rng.uniform();
    puffs.push_back(p);
  }
  const uint64_t noise_seed = mix_seeds(opt.seed, 0xC10D);
  const double noise_scale = nx / 12.0;  // lattice cells per x extent at octave 0
  float max_value = 0.0f;
  uint64_t active = 0;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const double ux = ((2.0 * x + 1.0) - nx) / nx;
        const double uy = ((2.0 * y + 1.0) - ny) / nx;
        const double uz = ((2.0 * z + 1.0) - nz) / nx;
        double shape = 0.0;
        for (const Puff& p : puffs) {
          const double dx = (ux - p.x) / p.r, dy = (uy - p.y) / (0.9 * p.r), dz = (uz - p.z) / p.r;
          shape = std::max(shape, 1.0 - (dx * dx + dy * dy + dz * dz));
        }
        if (shape <= -0.1) continue;  // no wisps detached from the body
        const double base = std::clamp((uy - floor_y) / 0.04, 0.0, 1.0);
        const double noise = fbm(noise_seed, x / noise_scale, y / noise_scale, z / noise_scale);
        const double d = (shape + 0.6 * (noise - 0.5)) * base;
        const double density = std::clamp((d - 0.05) * 3.0, 0.0, 1.0);
        if (density < 0.05) continue;  // a crisp edge: no faint fringe for big splats to smear
        const float v = float(density);
        g.values[(size_t(z) * ny + y) * nx + x] = v;
        max_value = std::max(max_value, v);
        ++active;
      }
  g.active_voxels = active;
  g.max_value = max_value;
  return g;
}

}  // namespace pyro
