#pragma once
// The sum of grid Gaussians (grid_gaussian.h) as a field over a grid's voxels: what the fit
// (gaussian_fit.h) and the lighting of fitted Gaussians (gaussian_lighting.h) visit. Internal to
// systems/runtime/cloud_import.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/io/vdb_reader.h"
#include "systems/runtime/cloud_import/grid_gaussian.h"
#include "systems/runtime/reference/parallel_rows.h"

namespace pyro::gaussian_field {

inline constexpr float kExtent2 = kAnisotropicExtent * kAnisotropicExtent;

// The grid's box grown by `margin` voxels on every side, as a dense array of floats (x fastest).
// Local index x (0 = the first stored voxel) is element x + margin.
struct FieldBox {
  int margin = 0;
  int n[3] = {0, 0, 0};
  size_t at(int x, int y, int z) const {
    return (size_t(z + margin) * n[1] + size_t(y + margin)) * n[0] + size_t(x + margin);
  }
  size_t size() const { return size_t(n[0]) * n[1] * n[2]; }
  int lo() const { return -margin; }
  int hi(int a) const { return n[a] - margin - 1; }  // last local index on axis a
};

inline FieldBox field_box(const DenseGrid& grid, int margin) {
  FieldBox b;
  b.margin = margin;
  for (int a = 0; a < 3; ++a) b.n[a] = grid.dims[a] + 2 * margin;
  return b;
}

// -rho over the grown box: the residual before any Gaussian is added.
inline std::vector<float> negative_density(const DenseGrid& grid, const FieldBox& box) {
  std::vector<float> r(box.size(), 0.0f);
  for (int z = 0; z < grid.dims[2]; ++z)
    for (int y = 0; y < grid.dims[1]; ++y)
      for (int x = 0; x < grid.dims[0]; ++x) r[box.at(x, y, z)] = -grid.at(x, y, z);
  return r;
}

// The range of planes [z0, z1] a Gaussian reaches (its truncation ellipsoid's box: half-extent
// 3 sqrt(Sigma_zz)), clipped to the grown box; empty when z0 > z1.
inline void plane_range(const GridGaussian& g, const FieldBox& box, int axis, int& lo, int& hi) {
  const glm::mat3 cov = glm::inverse(glm::transpose(g.shape) * g.shape);
  const float h = kAnisotropicExtent * std::sqrt(std::max(cov[axis][axis], 0.0f));
  lo = std::max(box.lo(), int(std::ceil(g.mean[axis] - h)));
  hi = std::min(box.hi(axis), int(std::floor(g.mean[axis] + h)));
}

// Calls f(index, u, v, e) for every voxel of plane z inside g's truncation ellipsoid: u = x - mean,
// v = A u, e = exp(-|v|^2 / 2). Along a row, |v|^2 = a t^2 + 2 (c0 . w) t + |w|^2 with t = x - mean.x,
// c0 = A's first column, a = |c0|^2 and w = A (0, dy, dz); the row's voxels inside are the t
// between its roots. From one voxel to the next, e is multiplied by exp(-(c0 . v) - a / 2), and
// that factor by exp(-a): two products a voxel instead of an exponential.
template <class F>
void visit_plane(const GridGaussian& g, const FieldBox& box, int z, int ylo, int yhi, F&& f) {
  const glm::vec3 c0 = g.shape[0], c1 = g.shape[1], c2 = g.shape[2];
  const float a = glm::dot(c0, c0);
  const float step_ratio = std::exp(-a);
  const float dz = float(z) - g.mean.z;
  for (int y = ylo; y <= yhi; ++y) {
    const float dy = float(y) - g.mean.y;
    const glm::vec3 w = c1 * dy + c2 * dz;
    const float b = glm::dot(c0, w), c = glm::dot(w, w) - kExtent2;
    const float disc = b * b - a * c;
    if (disc < 0.0f) continue;
    const float root = std::sqrt(disc);
    const int xlo = std::max(box.lo(), int(std::ceil(g.mean.x + (-b - root) / a)));
    const int xhi = std::min(box.hi(0), int(std::floor(g.mean.x + (-b + root) / a)));
    if (xlo > xhi) continue;
    size_t index = box.at(xlo, y, z);
    float t = float(xlo) - g.mean.x;
    glm::vec3 v = c0 * t + w;
    float e = std::exp(-0.5f * glm::dot(v, v));
    float ratio = std::exp(-glm::dot(c0, v) - 0.5f * a);
    for (int x = xlo; x <= xhi; ++x, ++index) {
      f(index, glm::vec3(t, dy, dz), v, e);
      e *= ratio;
      ratio *= step_ratio;
      t += 1.0f;
      v += c0;
    }
  }
}

template <class F>
void visit(const GridGaussian& g, const FieldBox& box, F&& f) {
  int zlo, zhi, ylo, yhi;
  plane_range(g, box, 2, zlo, zhi);
  plane_range(g, box, 1, ylo, yhi);
  for (int z = zlo; z <= zhi; ++z) visit_plane(g, box, z, ylo, yhi, f);
}

// Adds weight(i) * peak_i * e_i(x) of every Gaussian i to `field` (over the grown box). Each plane
// adds its Gaussians in index order on one thread, so the sums do not depend on the thread count.
template <class Weight>
void add_gaussians(std::vector<float>& r, const std::vector<GridGaussian>& gs, const FieldBox& box,
                   int threads, Weight&& weight) {
  std::vector<std::vector<uint32_t>> planes(box.n[2]);
  for (uint32_t i = 0; i < gs.size(); ++i) {
    int zlo, zhi;
    plane_range(gs[i], box, 2, zlo, zhi);
    for (int z = zlo; z <= zhi; ++z) planes[z + box.margin].push_back(i);
  }
  parallel_rows(box.n[2], threads, [&](int plane) {
    for (const uint32_t i : planes[plane]) {
      const GridGaussian& g = gs[i];
      const float w = weight(i) * g.peak;
      int ylo, yhi;
      plane_range(g, box, 1, ylo, yhi);
      visit_plane(g, box, plane - box.margin, ylo, yhi,
                  [&](size_t q, const glm::vec3&, const glm::vec3&, float e) { r[q] += w * e; });
    }
  });
}

// The residual f - rho over the grown box.
inline std::vector<float> residual(const DenseGrid& grid, const std::vector<GridGaussian>& gs,
                                   const FieldBox& box, int threads) {
  std::vector<float> r = negative_density(grid, box);
  add_gaussians(r, gs, box, threads, [](uint32_t) { return 1.0f; });
  return r;
}

// Each Gaussian's share of a squared residual r: the sum over its voxels of (what it adds there /
// the Gaussians' density sum there, `density_sum`) r^2.
inline std::vector<double> shares_of(const std::vector<GridGaussian>& gs, const FieldBox& box,
                                     const std::vector<float>& r, const std::vector<float>& density_sum,
                                     int threads) {
  std::vector<double> share(gs.size(), 0.0);
  parallel_rows(int(gs.size()), threads, [&](int i) {
    const GridGaussian& g = gs[i];
    double s = 0.0;
    visit(g, box, [&](size_t q, const glm::vec3&, const glm::vec3&, float e) {
      if (density_sum[q] > 0.0f) s += double(g.peak * e / density_sum[q]) * double(r[q]) * r[q];
    });
    share[i] = s;
  });
  return share;
}

}  // namespace pyro::gaussian_field
