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

// Transmittance to the light, exp(-optical depth), at every voxel that holds density (elsewhere
// it is never read: every use is weighted by the density).
std::vector<float> light_transmittance(const DenseGrid& grid, const VolumeMedium& medium, int threads) {
  std::vector<float> lit = light_optical_depth_sweep(grid, medium, threads);
  const int planes = grid.dims[2];
  const size_t plane = size_t(grid.dims[0]) * grid.dims[1];
  parallel_rows(planes, threads, [&](int z) {
    for (size_t i = size_t(z) * plane, e = i + plane; i < e; ++i)
      lit[i] = grid.values[i] != 0.0f ? std::exp(-lit[i]) : 1.0f;
  });
  return lit;
}

// Level l's cells from level l - 1's (l = 1: from the grid itself): sums over 2x2x2 children,
// cells past the finer level's edge holding 0.
void reduce_level(const DenseGrid& grid, const std::vector<float>& lit, const Level& fine, int l,
                  Level& lv, int threads) {
  const size_t cells = size_t(lv.m[0]) * lv.m[1] * lv.m[2];
  lv.sum.assign(cells, 0.0f);
  lv.sumsq.assign(cells, 0.0f);
  lv.sum_lit.assign(cells, 0.0f);
  lv.max.assign(cells, 0.0f);
  parallel_rows(lv.m[2], threads, [&](int z) {
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

// The mip pyramid, levels 0 (the grid's size) to `top`. Top-level cells, 2^top voxels on a side,
// cover the grid padded up to a whole number of them.
std::vector<Level> build_pyramid(const DenseGrid& grid, const std::vector<float>& lit, int top,
                                 int threads) {
  const int B = 1 << top;
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  std::vector<Level> levels(top + 1);
  for (int a = 0; a < 3; ++a) levels[0].m[a] = n[a];
  for (int l = 1; l <= top; ++l) {
    for (int a = 0; a < 3; ++a) levels[l].m[a] = ((n[a] + B - 1) / B) * (B >> l);
    reduce_level(grid, lit, levels[l - 1], l, levels[l], threads);
  }
  return levels;
}

// The octree walk over the pyramid (the merging rule in cloud_import.h): a block becomes one
// particle when its spread and its steps to its neighbours are within the tolerance, else its 8
// children are visited.
class BlockFitter {
 public:
  BlockFitter(const DenseGrid& grid, const std::vector<float>& lit, const std::vector<Level>& levels,
              const CloudImportOptions& opt)
      : grid_(grid), lit_(lit), levels_(levels), opt_(opt), med_(opt.medium) {
    const glm::dmat3 w3(grid.index_to_world);
    voxel_volume_ = std::abs(glm::determinant(w3));
    voxel_length_ = std::cbrt(voxel_volume_);
    ext_len_ = med_.extinction * voxel_length_;
  }

  // Appends the particles of block (x, y, z) at level l to `dst`, counting them per level.
  void visit(int l, int x, int y, int z, std::vector<GaussianParticle>& dst,
             std::vector<uint64_t>& per_level) const {
    const double b = double(1 << l);
    if (l == 0) {
      const Level& grid_level = levels_[0];
      if (x >= grid_level.m[0] || y >= grid_level.m[1] || z >= grid_level.m[2]) return;
      const size_t q = grid_level.at(x, y, z);
      const double v = grid_.values[q];
      if (ext_len_ * v < drop()) return;
      emit(dst, 0, x, y, z, v, lit_[q]);
      ++per_level[0];
      return;
    }
    const Level& c = levels_[l];
    const size_t q = c.at(x, y, z);
    if (ext_len_ * b * c.max[q] < drop()) return;
    const double cells = b * b * b;
    const double mean = c.sum[q] / cells;
    const double var = std::max(0.0, double(c.sumsq[q]) / cells - mean * mean);
    double step = 0.0;
    const int nb[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& d : nb) step = std::max(step, std::abs(mean_at(l, x + d[0], y + d[1], z + d[2]) - mean));
    const double tol = opt_.tau_tolerance;
    if (ext_len_ * b * std::sqrt(var) <= tol && ext_len_ * b * 0.5 * step <= tol) {
      emit(dst, l, x, y, z, mean, c.sum[q] > 0 ? c.sum_lit[q] / c.sum[q] : 1.0);
      ++per_level[l];
      return;
    }
    for (int dz = 0; dz < 2; ++dz)
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) visit(l - 1, 2 * x + dx, 2 * y + dy, 2 * z + dz, dst, per_level);
  }

 private:
  // Blocks whose whole optical depth is below this are dropped.
  double drop() const { return opt_.tau_tolerance / 64.0; }

  double mean_at(int l, int x, int y, int z) const {
    const Level& lv = levels_[l];
    if (x < 0 || y < 0 || z < 0 || x >= lv.m[0] || y >= lv.m[1] || z >= lv.m[2]) return 0.0;
    const double cells = double(1ull << (3 * l));
    return l == 0 ? grid_.values[lv.at(x, y, z)] : lv.sum[lv.at(x, y, z)] / cells;
  }

  // One Gaussian for block (x, y, z) at level l of mean density `mean` and mean transmittance
  // `mean_lit` (the model in cloud_import.h).
  void emit(std::vector<GaussianParticle>& dst, int l, int x, int y, int z, double mean,
            double mean_lit) const {
    const double b = double(1 << l);
    const glm::dvec4 centre_index(grid_.origin[0] + b * (x + 0.5) - 0.5,
                                  grid_.origin[1] + b * (y + 0.5) - 0.5,
                                  grid_.origin[2] + b * (z + 0.5) - 0.5, 1.0);
    const glm::dvec3 c = glm::dvec3(grid_.index_to_world * centre_index);
    const double s = opt_.kappa * b * voxel_length_;
    // tau0 = k s sqrt(2 pi) erf(3/sqrt 2), k = sigma_t V / ((2 pi)^(3/2) s^3).
    const double tau0 = med_.extinction * mean * b * b * b * voxel_volume_ * erf3_ /
                        (2.0 * std::numbers::pi * s * s);
    const double rho = std::min(-std::expm1(-tau0), 0.999);
    const glm::dvec3 col = glm::clamp(med_.albedo * (med_.light_color * mean_lit + med_.ambient),
                                      glm::dvec3(0.0), glm::dvec3(1.0));
    dst.push_back({float(c.x), float(c.y), float(c.z), float(3.0 * s), float(rho), float(col.x),
                   float(col.y), float(col.z)});
  }

  const DenseGrid& grid_;
  const std::vector<float>& lit_;
  const std::vector<Level>& levels_;
  const CloudImportOptions& opt_;
  const VolumeMedium& med_;
  double voxel_volume_ = 0, voxel_length_ = 0, ext_len_ = 0;
  const double erf3_ = std::erf(3.0 / std::numbers::sqrt2);
};

// Walks every top-level block, a slab of them per thread, and joins the slabs in z order (so the
// particles' order does not depend on the thread count).
std::vector<GaussianParticle> fit_blocks(const BlockFitter& fitter, const Level& top, int top_level,
                                         int threads, std::vector<uint64_t>& per_level) {
  std::vector<std::vector<GaussianParticle>> slabs(top.m[2]);
  std::vector<std::vector<uint64_t>> counts(top.m[2], std::vector<uint64_t>(top_level + 1, 0));
  parallel_rows(top.m[2], threads, [&](int z) {
    for (int y = 0; y < top.m[1]; ++y)
      for (int x = 0; x < top.m[0]; ++x) fitter.visit(top_level, x, y, z, slabs[z], counts[z]);
  });
  size_t total = 0;
  for (const auto& s : slabs) total += s.size();
  std::vector<GaussianParticle> out;
  out.reserve(total);
  for (int z = 0; z < top.m[2]; ++z) {
    out.insert(out.end(), slabs[z].begin(), slabs[z].end());
    for (int l = 0; l <= top_level; ++l) per_level[l] += counts[z][l];
  }
  return out;
}

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
  auto t0 = Clock::now();
  const std::vector<float> lit = light_transmittance(grid, opt.medium, opt.threads);
  rep.light_seconds = seconds_since(t0);

  t0 = Clock::now();
  const int top_level = std::max(0, opt.max_level);
  const std::vector<Level> levels = build_pyramid(grid, lit, top_level, opt.threads);
  const BlockFitter fitter(grid, lit, levels, opt);
  out = fit_blocks(fitter, levels[top_level], top_level, opt.threads, rep.particles_per_level);
  rep.particles = out.size();
  rep.fit_seconds = seconds_since(t0);
  if (report) *report = rep;
  return out;
}

}  // namespace pyro
