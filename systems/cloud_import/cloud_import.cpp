#include "systems/cloud_import/cloud_import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "systems/cloud_import/light_sweep.h"
#include "systems/reference/parallel_rows.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Per-level block statistics of the mip pyramid. Level 0 is the grid itself.
struct Level {
  int m[3] = {0, 0, 0};
  std::vector<float> sum, sumsq, sum_lit, max;
  size_t at(int x, int y, int z) const { return (size_t(z) * m[1] + y) * m[0] + x; }
};

}  // namespace

double default_extinction(const DenseGrid& grid, double target_depth) {
  if (grid.empty() || grid.max_value <= 0.0f) return 1.0;
  double shortest = 1e300;
  const glm::dmat3 w(grid.index_to_world);
  for (int a = 0; a < 3; ++a) shortest = std::min(shortest, grid.dims[a] * glm::length(w[a]));
  return target_depth / (double(grid.max_value) * shortest);
}

double tau_tolerance_for_error(double error) { return 4.0 * error; }

void grid_world_bounds(const DenseGrid& grid, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(1e300);
  hi = glm::dvec3(-1e300);
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec4 p(0, 0, 0, 1);
    for (int a = 0; a < 3; ++a)
      p[a] = grid.origin[a] + ((corner >> a) & 1 ? grid.dims[a] - 0.5 : -0.5);
    const glm::dvec3 w = glm::dvec3(grid.index_to_world * p);
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
}

std::vector<GaussianParticle> import_cloud(const DenseGrid& grid, const CloudImportOptions& opt,
                                           CloudImportReport* report) {
  CloudImportReport rep;
  rep.active_voxels = grid.active_voxels;
  rep.particles_per_level.assign(opt.max_level + 1, 0);
  std::vector<GaussianParticle> out;
  if (grid.empty()) {
    if (report) *report = rep;
    return out;
  }
  const VolumeMedium& med = opt.medium;

  // Lighting: transmittance to the light at every voxel.
  auto t0 = Clock::now();
  std::vector<float> lit = light_optical_depth_sweep(grid, med, opt.threads);
  // Transmittance, only where there is density (elsewhere it is never read: every use is
  // weighted by the density).
  {
    const int planes = grid.dims[2];
    const size_t plane = size_t(grid.dims[0]) * grid.dims[1];
    parallel_rows(planes, opt.threads, [&](int z) {
      for (size_t i = size_t(z) * plane, e = i + plane; i < e; ++i)
        lit[i] = grid.values[i] != 0.0f ? std::exp(-lit[i]) : 1.0f;
    });
  }
  rep.light_seconds = seconds_since(t0);

  t0 = Clock::now();
  const int L = std::max(0, opt.max_level);
  const int B = 1 << L;
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  std::vector<Level> levels(L + 1);
  for (int a = 0; a < 3; ++a) levels[0].m[a] = n[a];
  // Level 1 from the grid, level l + 1 from level l: sums over 2x2x2 children (cells past the
  // grid's edge hold 0). Top-level cells cover the padded grid.
  for (int l = 1; l <= L; ++l) {
    Level& lv = levels[l];
    for (int a = 0; a < 3; ++a) lv.m[a] = ((n[a] + B - 1) / B) * (B >> l);
    const size_t cells = size_t(lv.m[0]) * lv.m[1] * lv.m[2];
    lv.sum.assign(cells, 0.0f);
    lv.sumsq.assign(cells, 0.0f);
    lv.sum_lit.assign(cells, 0.0f);
    lv.max.assign(cells, 0.0f);
    const Level& fine = levels[l - 1];
    parallel_rows(lv.m[2], opt.threads, [&](int z) {
      for (int y = 0; y < lv.m[1]; ++y)
        for (int x = 0; x < lv.m[0]; ++x) {
          float s = 0, s2 = 0, sl = 0, mx = 0;
          for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
              for (int dx = 0; dx < 2; ++dx) {
                const int fx = 2 * x + dx, fy = 2 * y + dy, fz = 2 * z + dz;
                if (fx >= fine.m[0] || fy >= fine.m[1] || fz >= fine.m[2]) continue;
                const size_t q = fine.at(fx, fy, fz);
                if (l == 1) {
                  const float v = grid.values[q];
                  s += v;
                  s2 += v * v;
                  sl += v * lit[q];
                  mx = std::max(mx, v);
                } else {
                  s += fine.sum[q];
                  s2 += fine.sumsq[q];
                  sl += fine.sum_lit[q];
                  mx = std::max(mx, fine.max[q]);
                }
              }
          const size_t c = lv.at(x, y, z);
          lv.sum[c] = s;
          lv.sumsq[c] = s2;
          lv.sum_lit[c] = sl;
          lv.max[c] = mx;
        }
    });
  }

  // World geometry of a block.
  const glm::dmat3 w3(grid.index_to_world);
  const double voxel_volume = std::abs(glm::determinant(w3));
  const double voxel_length = std::cbrt(voxel_volume);
  const double erf3 = std::erf(3.0 / std::numbers::sqrt2);
  const double tol = opt.tau_tolerance;
  const double drop = tol / 64.0;

  const auto mean_at = [&](int l, int x, int y, int z) -> double {
    const Level& lv = levels[l];
    if (x < 0 || y < 0 || z < 0 || x >= lv.m[0] || y >= lv.m[1] || z >= lv.m[2]) return 0.0;
    const double cells = double(1ull << (3 * l));
    return l == 0 ? grid.values[lv.at(x, y, z)] : lv.sum[lv.at(x, y, z)] / cells;
  };
  const auto emit = [&](std::vector<GaussianParticle>& dst, int l, int x, int y, int z,
                        double mean, double mean_lit) {
    const double b = double(1 << l);
    const glm::dvec4 centre_index(grid.origin[0] + b * (x + 0.5) - 0.5,
                                  grid.origin[1] + b * (y + 0.5) - 0.5,
                                  grid.origin[2] + b * (z + 0.5) - 0.5, 1.0);
    const glm::dvec3 c = glm::dvec3(grid.index_to_world * centre_index);
    const double s = opt.kappa * b * voxel_length;
    // tau0 = k s sqrt(2 pi) erf(3/sqrt 2), k = sigma_t V / ((2 pi)^(3/2) s^3).
    const double tau0 = med.extinction * mean * b * b * b * voxel_volume * erf3 /
                        (2.0 * std::numbers::pi * s * s);
    const double rho = std::min(-std::expm1(-tau0), 0.999);
    const glm::dvec3 col = glm::clamp(med.albedo * (med.light_color * mean_lit + med.ambient),
                                      glm::dvec3(0.0), glm::dvec3(1.0));
    dst.push_back({float(c.x), float(c.y), float(c.z), float(3.0 * s), float(rho), float(col.x),
                   float(col.y), float(col.z)});
  };

  // Recursive split of one block.
  struct Walker {
    const decltype(levels)& lv;
    const DenseGrid& grid;
    const std::vector<float>& lit;
    const decltype(mean_at)& mean_of;
    const decltype(emit)& emit_particle;
    double ext_len, tol, drop;
    std::vector<GaussianParticle>& dst;
    std::vector<uint64_t>& per_level;
    void visit(int l, int x, int y, int z) {
      const double b = double(1 << l);
      if (l == 0) {
        if (x >= lv[0].m[0] || y >= lv[0].m[1] || z >= lv[0].m[2]) return;
        const size_t q = lv[0].at(x, y, z);
        const double v = grid.values[q];
        if (ext_len * v < drop) return;
        emit_particle(dst, 0, x, y, z, v, lit[q]);
        ++per_level[0];
        return;
      }
      const Level& c = lv[l];
      const size_t q = c.at(x, y, z);
      if (ext_len * b * c.max[q] < drop) return;
      const double cells = b * b * b;
      const double mean = c.sum[q] / cells;
      const double var = std::max(0.0, double(c.sumsq[q]) / cells - mean * mean);
      double step = 0.0;
      const int nb[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      for (const auto& d : nb)
        step = std::max(step, std::abs(mean_of(l, x + d[0], y + d[1], z + d[2]) - mean));
      if (ext_len * b * std::sqrt(var) <= tol && ext_len * b * 0.5 * step <= tol) {
        emit_particle(dst, l, x, y, z, mean, c.sum[q] > 0 ? c.sum_lit[q] / c.sum[q] : 1.0);
        ++per_level[l];
        return;
      }
      for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) visit(l - 1, 2 * x + dx, 2 * y + dy, 2 * z + dz);
    }
  };

  const Level& top = levels[L];
  std::vector<std::vector<GaussianParticle>> slabs(top.m[2]);
  std::vector<std::vector<uint64_t>> counts(top.m[2], std::vector<uint64_t>(L + 1, 0));
  const double ext_len = med.extinction * voxel_length;
  parallel_rows(top.m[2], opt.threads, [&](int z) {
    Walker w{levels, grid, lit, mean_at, emit, ext_len, tol, drop, slabs[z], counts[z]};
    for (int y = 0; y < top.m[1]; ++y)
      for (int x = 0; x < top.m[0]; ++x) w.visit(L, x, y, z);
  });
  size_t total = 0;
  for (const auto& s : slabs) total += s.size();
  out.reserve(total);
  for (int z = 0; z < top.m[2]; ++z) {
    out.insert(out.end(), slabs[z].begin(), slabs[z].end());
    for (int l = 0; l <= L; ++l) rep.particles_per_level[l] += counts[z][l];
  }
  rep.particles = out.size();
  rep.fit_seconds = seconds_since(t0);
  if (report) *report = rep;
  return out;
}

}  // namespace pyro
