#include "systems/runtime/cloud_import/cloud_import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "engine/core/stopwatch.h"
#include "systems/runtime/cloud_import/light_sweep.h"
#include "systems/runtime/reference/parallel_rows.h"

namespace pyro {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBrickShift = SparseGrid::kBrickShift;  // a brick is one block of level 3
constexpr size_t kAbsent = std::numeric_limits<size_t>::max();

// One cell's statistics: sums of the density, of its square and of the density times the
// transmittance to the light, and the largest density (at least 0).
struct Cell {
  float sum = 0, sumsq = 0, sum_lit = 0, max = 0;
};

// Per-level block statistics of the mip pyramid. Level 0 is the grid itself. Levels up to 3 live
// in the bricks: a stored brick holds (8 >> l)^3 cells of level l, slot after slot like the
// grid's values (level 0: the values and the transmittance themselves), and an absent brick's
// cells are all 0. Levels 4 and up are dense over the padded box (at most box / 4096 cells).
struct Level {
  int m[3] = {0, 0, 0};  // cells per axis: the box at level 0, ceil(n / 2^top) * 2^(top - l) above
  int side = 0;          // cells per brick side (levels up to 3), 0 for a dense level
  std::vector<float> sum, sumsq, sum_lit, max;
  bool in_range(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < m[0] && y < m[1] && z < m[2];
  }
};

class Pyramid {
 public:
  Pyramid(const SparseGrid& grid, const std::vector<float>& lit, int top, int threads);

  const Level& level(int l) const { return levels_[l]; }
  // Where cell (x, y, z) of level l (in range) is stored, kAbsent when in an absent brick.
  size_t cell(int l, int x, int y, int z) const {
    const Level& lv = levels_[l];
    if (lv.side == 0) return (size_t(z) * lv.m[1] + size_t(y)) * lv.m[0] + size_t(x);
    const int shift = kBrickShift - l, mask = lv.side - 1;
    const int32_t slot = grid_.slot(x >> shift, y >> shift, z >> shift);
    if (slot < 0) return kAbsent;
    return size_t(slot) * size_t(lv.side * lv.side * lv.side) +
           size_t(((z & mask) * lv.side + (y & mask)) * lv.side + (x & mask));
  }
  Cell stats(int l, int x, int y, int z) const {
    const size_t q = cell(l, x, y, z);
    if (q == kAbsent) return {};
    const Level& lv = levels_[l];
    return {lv.sum[q], lv.sumsq[q], lv.sum_lit[q], lv.max[q]};
  }

 private:
  void reduce_brick(int32_t slot, int l);
  void reduce_dense(int l, int threads);
  Cell child(int l, int32_t slot, int fx, int fy, int fz) const;

  const SparseGrid& grid_;
  const std::vector<float>& lit_;
  std::vector<Level> levels_;
};

// The pyramid, levels 0 (the grid's size) to `top`. Top-level cells, 2^top voxels on a side,
// cover the grid padded up to a whole number of them.
Pyramid::Pyramid(const SparseGrid& grid, const std::vector<float>& lit, int top, int threads)
    : grid_(grid), lit_(lit), levels_(top + 1) {
  const int B = 1 << top;
  for (int l = 0; l <= top; ++l) {
    Level& lv = levels_[l];
    for (int a = 0; a < 3; ++a) lv.m[a] = l == 0 ? grid.dims[a] : ((grid.dims[a] + B - 1) / B) * (B >> l);
    lv.side = l <= kBrickShift ? SparseGrid::kBrickSide >> l : 0;
    if (l == 0) continue;
    const size_t cells = lv.side ? grid.bricks() * size_t(lv.side * lv.side * lv.side)
                                 : size_t(lv.m[0]) * lv.m[1] * lv.m[2];
    lv.sum.assign(cells, 0.0f);
    lv.sumsq.assign(cells, 0.0f);
    lv.sum_lit.assign(cells, 0.0f);
    lv.max.assign(cells, 0.0f);
  }
  const int bricked_top = std::min(top, kBrickShift);
  parallel_rows(int(grid.bricks()), threads, [&](int slot) {
    for (int l = 1; l <= bricked_top; ++l) reduce_brick(slot, l);
  });
  for (int l = kBrickShift + 1; l <= top; ++l) reduce_dense(l, threads);
}

// Child (fx, fy, fz), brick-local, of a level-l cell of brick `slot` (level l - 1's statistics;
// level 0: the voxel's value and transmittance).
Cell Pyramid::child(int l, int32_t slot, int fx, int fy, int fz) const {
  const Level& fine = levels_[l - 1];
  const size_t q = size_t(slot) * size_t(fine.side * fine.side * fine.side) +
                   size_t((fz * fine.side + fy) * fine.side + fx);
  if (l == 1) {
    const float v = grid_.values[q];
    return {v, v * v, v * lit_[q], v};
  }
  return {fine.sum[q], fine.sumsq[q], fine.sum_lit[q], fine.max[q]};
}

// Level l's cells of one brick from level l - 1's: sums over 2x2x2 children (voxels past the
// box hold 0, as the dense pyramid's missing cells would add nothing).
void Pyramid::reduce_brick(int32_t slot, int l) {
  Level& lv = levels_[l];
  const int c = lv.side;
  for (int z = 0; z < c; ++z)
    for (int y = 0; y < c; ++y)
      for (int x = 0; x < c; ++x) {
        float s = 0, s2 = 0, sl = 0, mx = 0;
        for (int dz = 0; dz < 2; ++dz)
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              const Cell f = child(l, slot, 2 * x + dx, 2 * y + dy, 2 * z + dz);
              s += f.sum;
              s2 += f.sumsq;
              sl += f.sum_lit;
              mx = std::max(mx, f.max);
            }
        const size_t q = size_t(slot) * size_t(c * c * c) + size_t((z * c + y) * c + x);
        lv.sum[q] = s;
        lv.sumsq[q] = s2;
        lv.sum_lit[q] = sl;
        lv.max[q] = mx;
      }
}

// A dense level (4 and up) from the level below: sums over 2x2x2 children, absent ones adding
// nothing.
void Pyramid::reduce_dense(int l, int threads) {
  Level& lv = levels_[l];
  const Level& fine = levels_[l - 1];
  parallel_rows(lv.m[2], threads, [&](int z) {
    for (int y = 0; y < lv.m[1]; ++y)
      for (int x = 0; x < lv.m[0]; ++x) {
        float s = 0, s2 = 0, sl = 0, mx = 0;
        for (int dz = 0; dz < 2; ++dz)
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
              const int fx = 2 * x + dx, fy = 2 * y + dy, fz = 2 * z + dz;
              if (!fine.in_range(fx, fy, fz)) continue;
              const size_t q = cell(l - 1, fx, fy, fz);
              if (q == kAbsent) continue;
              s += fine.sum[q];
              s2 += fine.sumsq[q];
              sl += fine.sum_lit[q];
              mx = std::max(mx, fine.max[q]);
            }
        const size_t c = cell(l, x, y, z);
        lv.sum[c] = s;
        lv.sumsq[c] = s2;
        lv.sum_lit[c] = sl;
        lv.max[c] = mx;
      }
  });
}

// The octree walk over the pyramid (the merging rule in cloud_import.h): a block becomes one
// particle when its spread and its steps to its neighbours are within the tolerance, else its 8
// children are visited.
class BlockFitter {
 public:
  BlockFitter(const SparseGrid& grid, const std::vector<float>& lit, const Pyramid& pyramid,
              const CloudImportOptions& opt)
      : grid_(grid), lit_(lit), pyr_(pyramid), opt_(opt), med_(opt.medium) {
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
      if (!pyr_.level(0).in_range(x, y, z)) return;
      const size_t q = pyr_.cell(0, x, y, z);
      const double v = q == kAbsent ? 0.0f : grid_.values[q];
      if (ext_len_ * v < drop()) return;
      emit(dst, 0, x, y, z, v, q == kAbsent ? 1.0f : lit_[q]);
      ++per_level[0];
      return;
    }
    const Cell c = pyr_.stats(l, x, y, z);
    if (ext_len_ * b * c.max < drop()) return;
    const double cells = b * b * b;
    const double mean = c.sum / cells;
    const double var = std::max(0.0, double(c.sumsq) / cells - mean * mean);
    double step = 0.0;
    const int nb[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& d : nb) step = std::max(step, std::abs(mean_at(l, x + d[0], y + d[1], z + d[2]) - mean));
    const double tol = opt_.tau_tolerance;
    if (ext_len_ * b * std::sqrt(var) <= tol && ext_len_ * b * 0.5 * step <= tol) {
      emit(dst, l, x, y, z, mean, c.sum > 0 ? c.sum_lit / c.sum : 1.0);
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
    if (!pyr_.level(l).in_range(x, y, z)) return 0.0;
    const double cells = double(1ull << (3 * l));
    if (l == 0) {
      const size_t q = pyr_.cell(0, x, y, z);
      return q == kAbsent ? 0.0f : grid_.values[q];
    }
    return pyr_.stats(l, x, y, z).sum / cells;
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

  const SparseGrid& grid_;
  const std::vector<float>& lit_;
  const Pyramid& pyr_;
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
    std::vector<GaussianParticle>().swap(slabs[z]);
    for (int l = 0; l <= top_level; ++l) per_level[l] += counts[z][l];
  }
  return out;
}

}  // namespace

double default_extinction(const GridHeader& grid, double target_depth) {
  if (grid.box_voxels() == 0 || grid.max_value <= 0.0f) return 1.0;
  double shortest = 1e300;
  const glm::dmat3 w(grid.index_to_world);
  for (int a = 0; a < 3; ++a) shortest = std::min(shortest, grid.dims[a] * glm::length(w[a]));
  return target_depth / (double(grid.max_value) * shortest);
}

double tau_tolerance_for_error(double error) { return 4.0 * error; }

void grid_world_bounds(const GridHeader& grid, glm::dvec3& lo, glm::dvec3& hi) {
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

std::vector<GaussianParticle> import_cloud(const SparseGrid& grid, const CloudImportOptions& opt,
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
  const std::vector<float> lit = light_transmittance_sweep(grid, opt.medium, opt.threads);
  rep.light_seconds = seconds_since(t0);

  t0 = Clock::now();
  const int top_level = std::max(0, opt.max_level);
  const Pyramid pyramid(grid, lit, top_level, opt.threads);
  const BlockFitter fitter(grid, lit, pyramid, opt);
  out = fit_blocks(fitter, pyramid.level(top_level), top_level, opt.threads, rep.particles_per_level);
  rep.particles = out.size();
  rep.fit_seconds = seconds_since(t0);
  if (report) *report = rep;
  return out;
}

std::vector<GaussianParticle> import_cloud(const DenseGrid& grid, const CloudImportOptions& opt,
                                           CloudImportReport* report) {
  return import_cloud(sparse_from_dense(grid), opt, report);
}

}  // namespace pyro
