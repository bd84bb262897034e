#pragma once
// Trilinear reconstruction of a dense grid (engine/io/vdb_reader.h) at a continuous position in
// the grid's local index space (0 = the first stored voxel's centre). Outside the stored box the
// grid holds its background 0, so values fall linearly to 0 over the one voxel past the edge.
#include <cmath>

#include "engine/io/vdb_reader.h"
#include "engine/volume/sparse_grid.h"

namespace pyro {

// f: the dense array (x fastest) of a grid with dimensions n[0..2].
inline float sample_trilinear(const float* f, const int n[3], double x, double y, double z) {
  if (!(x > -1.0 && y > -1.0 && z > -1.0 && x < n[0] && y < n[1] && z < n[2])) return 0.0f;
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int x0 = int(fx), y0 = int(fy), z0 = int(fz);
  const float tx = float(x - fx), ty = float(y - fy), tz = float(z - fz);
  const auto v = [&](int i, int j, int k) -> float {
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return 0.0f;
    return f[(size_t(k) * n[1] + j) * n[0] + i];
  };
  const float c00 = v(x0, y0, z0) + tx * (v(x0 + 1, y0, z0) - v(x0, y0, z0));
  const float c10 = v(x0, y0 + 1, z0) + tx * (v(x0 + 1, y0 + 1, z0) - v(x0, y0 + 1, z0));
  const float c01 = v(x0, y0, z0 + 1) + tx * (v(x0 + 1, y0, z0 + 1) - v(x0, y0, z0 + 1));
  const float c11 = v(x0, y0 + 1, z0 + 1) + tx * (v(x0 + 1, y0 + 1, z0 + 1) - v(x0, y0 + 1, z0 + 1));
  const float c0 = c00 + ty * (c10 - c00), c1 = c01 + ty * (c11 - c01);
  return c0 + tz * (c1 - c0);
}

// sample_trilinear over a sparse grid's bricks (absent bricks and everything outside hold 0).
inline float sample_trilinear_sparse(const SparseGrid& g, double x, double y, double z) {
  if (!(x > -1.0 && y > -1.0 && z > -1.0 && x < g.dims[0] && y < g.dims[1] && z < g.dims[2])) return 0.0f;
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int x0 = int(fx), y0 = int(fy), z0 = int(fz);
  const float tx = float(x - fx), ty = float(y - fy), tz = float(z - fz);
  const auto v = [&](int i, int j, int k) { return g.at(i, j, k); };
  const float c00 = v(x0, y0, z0) + tx * (v(x0 + 1, y0, z0) - v(x0, y0, z0));
  const float c10 = v(x0, y0 + 1, z0) + tx * (v(x0 + 1, y0 + 1, z0) - v(x0, y0 + 1, z0));
  const float c01 = v(x0, y0, z0 + 1) + tx * (v(x0 + 1, y0, z0 + 1) - v(x0, y0, z0 + 1));
  const float c11 = v(x0, y0 + 1, z0 + 1) + tx * (v(x0 + 1, y0 + 1, z0 + 1) - v(x0, y0 + 1, z0 + 1));
  const float c0 = c00 + ty * (c10 - c00), c1 = c01 + ty * (c11 - c01);
  return c0 + tz * (c1 - c0);
}

// Like sample_trilinear but clamps the position into the stored box (for fields such as the
// optical depth to the light, which have no natural background).
inline float sample_trilinear_clamped(const float* f, const int n[3], double x, double y, double z) {
  const auto clampd = [](double v, int hi) { return v < 0.0 ? 0.0 : v > hi - 1 ? double(hi - 1) : v; };
  x = clampd(x, n[0]);
  y = clampd(y, n[1]);
  z = clampd(z, n[2]);
  const int x0 = std::min(int(x), n[0] - 1), y0 = std::min(int(y), n[1] - 1), z0 = std::min(int(z), n[2] - 1);
  const int x1 = std::min(x0 + 1, n[0] - 1), y1 = std::min(y0 + 1, n[1] - 1), z1 = std::min(z0 + 1, n[2] - 1);
  const float tx = float(x - x0), ty = float(y - y0), tz = float(z - z0);
  const auto v = [&](int i, int j, int k) { return f[(size_t(k) * n[1] + j) * n[0] + i]; };
  const float c00 = v(x0, y0, z0) + tx * (v(x1, y0, z0) - v(x0, y0, z0));
  const float c10 = v(x0, y1, z0) + tx * (v(x1, y1, z0) - v(x0, y1, z0));
  const float c01 = v(x0, y0, z1) + tx * (v(x1, y0, z1) - v(x0, y0, z1));
  const float c11 = v(x0, y1, z1) + tx * (v(x1, y1, z1) - v(x0, y1, z1));
  const float c0 = c00 + ty * (c10 - c00), c1 = c01 + ty * (c11 - c01);
  return c0 + tz * (c1 - c0);
}

// Ray (origin o, direction d, any length) against the box [lo, hi] on every axis (slab method,
// Kay & Kajiya 1986). Returns false when it misses; otherwise the parameter interval.
inline bool intersect_box(const double o[3], const double d[3], const double lo[3],
                          const double hi[3], double& t0, double& t1) {
  t0 = -1e300;
  t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

}  // namespace pyro
