#pragma once
// The importer as it was before it read sparse grids: a light sweep over the whole box and a mip
// pyramid dense over the whole box, then the same octree walk. Kept here, verbatim, as the
// specification the sparse importer (systems/runtime/cloud_import/cloud_import.h) must reproduce bit for
// bit, particles and order, on every grid.
#include <algorithm>
#include <barrier>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/reference/parallel_rows.h"
#include "systems/runtime/reference/volume_reference.h"

namespace pyro::oracle {



inline constexpr int kPad = 2;

// How the sweep walks the grid: slices across axis a, visited from the light's side; in each
// slice, rows along q with voxels along p (the smaller stride innermost). The point one slice
// towards the light is offset by (vp, vq) in the slice, the same for every voxel, so the bilinear
// weights (tp, tq) and the integer offsets (op, oq) are too.
struct SweepGeometry {
  int a = 0, p = 1, q = 2;
  int n[3] = {0, 0, 0};
  size_t stride[3] = {0, 0, 0};
  int sa = 1;          // the light lies towards +a when sa = 1
  int first = 0;       // the slice nearest the light
  float step_tau = 0;  // half the extinction over one slice step (the trapezoid rule's weight)
  int op = 0, oq = 0;  // each in {-1, 0, 1}
  float tp = 0, tq = 0;
};

inline SweepGeometry sweep_geometry(const DenseGrid& grid, const VolumeMedium& medium) {
  SweepGeometry g;
  const glm::dmat3 to_index(world_to_local_index(grid));
  const glm::dvec3 u = to_index * -glm::normalize(medium.light_direction);  // index per world unit
  for (int k = 1; k < 3; ++k)
    if (std::abs(u[k]) > std::abs(u[g.a])) g.a = k;
  for (int k = 0; k < 3; ++k) g.n[k] = grid.dims[k];
  g.stride[0] = 1;
  g.stride[1] = size_t(g.n[0]);
  g.stride[2] = size_t(g.n[0]) * g.n[1];
  // In-slice axes: p innermost (smaller stride), q outer.
  g.p = (g.a + 1) % 3;
  g.q = (g.a + 2) % 3;
  if (g.stride[g.p] > g.stride[g.q]) std::swap(g.p, g.q);
  const double ua = std::abs(u[g.a]);
  const double world_step = 1.0 / ua;                // world length of one slice step
  const double vp = u[g.p] / ua, vq = u[g.q] / ua;  // in-slice offset of the upstream point, |v| <= 1
  g.sa = u[g.a] > 0 ? 1 : -1;
  g.step_tau = float(0.5 * world_step * medium.extinction);
  g.first = g.sa > 0 ? g.n[g.a] - 1 : 0;
  g.op = int(std::floor(vp));
  g.oq = int(std::floor(vq));
  g.tp = float(vp - g.op);
  g.tq = float(vq - g.oq);
  return g;
}

// A sweep worker's copies of the two upstream rows, zero-padded by kPad on both sides,
// so that the bilinear lookups need no bounds checks.
struct UpstreamRows {
  std::vector<float> t0, t1, r0, r1;  // optical depth (t) and density (r) of rows q + oq, q + oq + 1
  explicit UpstreamRows(int np) : t0(np + 2 * kPad), t1(np + 2 * kPad), r0(np + 2 * kPad), r1(np + 2 * kPad) {}
};

inline void load_upstream_row(const SweepGeometry& g, const float* f, const float* d, int up, int row,
                       std::vector<float>& tau, std::vector<float>& rho) {
  if (row < 0 || row >= g.n[g.q]) {
    std::fill(tau.begin(), tau.end(), 0.0f);
    std::fill(rho.begin(), rho.end(), 0.0f);
    return;
  }
  const size_t base = size_t(up) * g.stride[g.a] + size_t(row) * g.stride[g.q];
  for (int i = 0; i < g.n[g.p]; ++i) {
    tau[kPad + i] = d[base + size_t(i) * g.stride[g.p]];
    rho[kPad + i] = f[base + size_t(i) * g.stride[g.p]];
  }
}

// Row j of slice s: the depth one slice towards the light (bilinear) plus the trapezoid step.
inline void sweep_row(const SweepGeometry& g, const float* f, float* d, int s, int j, UpstreamRows& up_rows) {
  const int np = g.n[g.p];
  const int up = s + g.sa;  // the slice towards the light
  const size_t row = size_t(s) * g.stride[g.a] + size_t(j) * g.stride[g.q];
  if (up < 0 || up >= g.n[g.a]) {
    for (int i = 0; i < np; ++i) {
      const size_t here = row + size_t(i) * g.stride[g.p];
      d[here] = g.step_tau * f[here];
    }
    return;
  }
  load_upstream_row(g, f, d, up, j + g.oq, up_rows.t0, up_rows.r0);
  load_upstream_row(g, f, d, up, j + g.oq + 1, up_rows.t1, up_rows.r1);
  const float* a0 = up_rows.t0.data() + kPad + g.op;
  const float* a1 = up_rows.t1.data() + kPad + g.op;
  const float* b0 = up_rows.r0.data() + kPad + g.op;
  const float* b1 = up_rows.r1.data() + kPad + g.op;
  const float tp = g.tp, tq = g.tq;
  for (int i = 0; i < np; ++i) {
    const float tau_up = (1 - tq) * ((1 - tp) * a0[i] + tp * a0[i + 1]) +
                         tq * ((1 - tp) * a1[i] + tp * a1[i + 1]);
    const float rho_up = (1 - tq) * ((1 - tp) * b0[i] + tp * b0[i + 1]) +
                         tq * ((1 - tp) * b1[i] + tp * b1[i + 1]);
    const size_t here = row + size_t(i) * g.stride[g.p];
    d[here] = tau_up + g.step_tau * (f[here] + rho_up);
  }
}


// Speed (the Disney cloud's 1.67 M dense voxels): the slice's two in-slice axes are walked with
// the one of smaller stride innermost (x whenever x is not the sweep axis), the two upstream rows
// are first copied into zero-padded buffers so the bilinear lookups need no bounds checks, and the
// rows of a slice are shared among threads that meet at a barrier between slices. Every voxel's
// value is computed by the same expression from the same inputs whoever computes it, so the result
// does not depend on the thread count (tested).
inline std::vector<float> dense_light_sweep(const DenseGrid& grid, const VolumeMedium& medium,
                                             int threads) {
  std::vector<float> depth(grid.values.size(), 0.0f);
  if (grid.empty()) return depth;
  const SweepGeometry g = sweep_geometry(grid, medium);
  const float* f = grid.values.data();
  float* d = depth.data();
  const int nq = g.n[g.q];
  int t = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  t = std::max(1, std::min(t, nq));
  std::barrier sync(t);
  const auto work = [&](int k) {
    UpstreamRows up_rows(g.n[g.p]);
    for (int s = g.first; s >= 0 && s < g.n[g.a]; s -= g.sa) {
      for (int j = k; j < nq; j += t) sweep_row(g, f, d, s, j, up_rows);
      sync.arrive_and_wait();  // the next slice reads this one
    }
  };
  if (t == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (int k = 1; k < t; ++k) pool.emplace_back(work, k);
    work(0);
    for (std::thread& th : pool) th.join();
  }
  return depth;
}

// Per-level block statistics of the mip pyramid. Level 0 is the grid itself.
struct Level {
  int m[3] = {0, 0, 0};
  std::vector<float> sum, sumsq, sum_lit, max;
  size_t at(int x, int y, int z) const { return (size_t(z) * m[1] + y) * m[0] + x; }
};

// Transmittance to the light, exp(-optical depth), at every voxel that holds density (elsewhere
// it is never read: every use is weighted by the density).
inline std::vector<float> light_transmittance(const DenseGrid& grid, const VolumeMedium& medium, int threads) {
  std::vector<float> lit = dense_light_sweep(grid, medium, threads);
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
inline void reduce_level(const DenseGrid& grid, const std::vector<float>& lit, const Level& fine, int l,
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
inline std::vector<Level> build_pyramid(const DenseGrid& grid, const std::vector<float>& lit, int top,
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
inline std::vector<GaussianParticle> fit_blocks(const BlockFitter& fitter, const Level& top, int top_level,
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

inline std::vector<GaussianParticle> dense_import(const DenseGrid& grid, const CloudImportOptions& opt) {
  if (grid.empty()) return {};
  std::vector<uint64_t> per_level(opt.max_level + 1, 0);
  const std::vector<float> lit = light_transmittance(grid, opt.medium, opt.threads);
  const int top_level = std::max(0, opt.max_level);
  const std::vector<Level> levels = build_pyramid(grid, lit, top_level, opt.threads);
  const BlockFitter fitter(grid, lit, levels, opt);
  return fit_blocks(fitter, levels[top_level], top_level, opt.threads, per_level);
}

}  // namespace pyro::oracle
