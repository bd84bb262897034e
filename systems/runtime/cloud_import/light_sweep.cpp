#include "systems/runtime/cloud_import/light_sweep.h"

#include <algorithm>
#include <barrier>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "systems/runtime/reference/volume_reference.h"

namespace pyro {

namespace {

constexpr int kPad = 2;  // zero columns on both sides of a slice row, zero rows above and below

// How the sweep walks the grid: slices across axis a, visited from the light's side; in each
// slice, rows along q with voxels along p (the smaller stride of the dense layout innermost). The
// point one slice towards the light is offset by (vp, vq) in the slice, the same for every voxel,
// so the bilinear weights (tp, tq) and the integer offsets (op, oq) are too.
struct SweepGeometry {
  int a = 0, p = 1, q = 2;
  int n[3] = {0, 0, 0};
  int sa = 1;          // the light lies towards +a when sa = 1
  int first = 0;       // the slice nearest the light
  float step_tau = 0;  // half the extinction over one slice step (the trapezoid rule's weight)
  int op = 0, oq = 0;  // each in {-1, 0, 1}
  float tp = 0, tq = 0;
};

SweepGeometry sweep_geometry(const GridHeader& grid, const VolumeMedium& medium) {
  SweepGeometry g;
  const glm::dmat3 to_index(world_to_local_index(grid));
  const glm::dvec3 u = to_index * -glm::normalize(medium.light_direction);  // index per world unit
  for (int k = 1; k < 3; ++k)
    if (std::abs(u[k]) > std::abs(u[g.a])) g.a = k;
  for (int k = 0; k < 3; ++k) g.n[k] = grid.dims[k];
  // In-slice axes: p innermost (the smaller stride in the dense layout, x fastest), q outer.
  const size_t stride[3] = {1, size_t(g.n[0]), size_t(g.n[0]) * g.n[1]};
  g.p = (g.a + 1) % 3;
  g.q = (g.a + 2) % 3;
  if (stride[g.p] > stride[g.q]) std::swap(g.p, g.q);
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

// Two slices (the one being swept and the one towards the light) of density and depth, each row
// zero-padded by kPad on both sides and kPad zero rows above and below, so that the bilinear
// lookups need no bounds checks; and per row whether it holds anything but zeros (bits all 0).
class SliceBuffers {
 public:
  explicit SliceBuffers(const SweepGeometry& g)
      : np_(size_t(g.n[g.p])), stride_(np_ + 2 * kPad), rows_(size_t(g.n[g.q]) + 2 * kPad) {
    for (int b = 0; b < 2; ++b) {
      density_[b].assign(stride_ * rows_, 0.0f);
      depth_[b].assign(stride_ * rows_, 0.0f);
      live_[b].assign(rows_, 0);
    }
  }
  // Row j (may be -kPad .. n_q + kPad - 1) of buffer b: its first voxel.
  float* density(int b, int j) { return density_[b].data() + size_t(j + kPad) * stride_ + kPad; }
  float* depth(int b, int j) { return depth_[b].data() + size_t(j + kPad) * stride_ + kPad; }
  bool live(int b, int j) const { return live_[b][size_t(j + kPad)] != 0; }
  // Row j of buffer b after it was swept: notes whether it holds anything but zeros.
  void note_row(int b, int j) {
    const float* d = depth(b, j);
    const float* f = density(b, j);
    uint32_t bits = 0;
    for (size_t i = 0; i < np_; ++i) {
      uint32_t u, v;
      std::memcpy(&u, d + i, sizeof u);
      std::memcpy(&v, f + i, sizeof v);
      bits |= u | v;
    }
    live_[b][size_t(j + kPad)] = bits != 0;
  }
  // Row j of buffer b made all zeros (what sweeping zeros gives), cheaply when it is already.
  void clear_row(int b, int j) {
    if (!live(b, j)) return;
    std::fill(density(b, j), density(b, j) + np_, 0.0f);
    std::fill(depth(b, j), depth(b, j) + np_, 0.0f);
    live_[b][size_t(j + kPad)] = 0;
  }

 private:
  size_t np_, stride_, rows_;
  std::vector<float> density_[2], depth_[2];
  std::vector<uint8_t> live_[2];
};

// Row j of a slice: the depth one slice towards the light (bilinear in rows u0, u1 of depth and
// density there, offset by op) plus the trapezoid step; `first`: no slice towards the light.
void sweep_row(const SweepGeometry& g, bool first, const float* f, float* d, const float* t0,
               const float* t1, const float* r0, const float* r1) {
  const int np = g.n[g.p];
  if (first) {
    for (int i = 0; i < np; ++i) d[i] = g.step_tau * f[i];
    return;
  }
  const float* a0 = t0 + g.op;
  const float* a1 = t1 + g.op;
  const float* b0 = r0 + g.op;
  const float* b1 = r1 + g.op;
  const float tp = g.tp, tq = g.tq;
  for (int i = 0; i < np; ++i) {
    const float tau_up = (1 - tq) * ((1 - tp) * a0[i] + tp * a0[i + 1]) +
                         tq * ((1 - tp) * a1[i] + tp * a1[i + 1]);
    const float rho_up = (1 - tq) * ((1 - tp) * b0[i] + tp * b0[i + 1]) +
                         tq * ((1 - tp) * b1[i] + tp * b1[i + 1]);
    d[i] = tau_up + g.step_tau * (f[i] + rho_up);
  }
}

// The sweep, for any storage: gather(s, j, row) fills row j of slice s with density (n_p values
// along p), scatter(s, j, depth, density) takes its depth, and stored(s, j) says whether that row
// may hold density (false: all 0). The rows of a slice are shared among threads that meet at a
// barrier between slices (the next slice reads this one); every voxel's value is computed by the
// same expression from the same inputs whoever computes it, so the result does not depend on the
// thread count. A row without density whose two upstream rows are all zeros sweeps to zeros
// (every product and sum of +0 is +0): it is cleared, not swept, and nothing is scattered.
template <class Gather, class Scatter, class Stored>
void sweep_slices(const SweepGeometry& g, int threads, Gather&& gather, Scatter&& scatter, Stored&& stored) {
  const int nq = g.n[g.q];
  int t = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  t = std::max(1, std::min(t, nq));
  SliceBuffers buffers(g);
  std::barrier sync(t);
  const auto work = [&](int k) {
    int b = 0;
    for (int s = g.first; s >= 0 && s < g.n[g.a]; s -= g.sa, b ^= 1) {
      const bool first = s == g.first;
      for (int j = k; j < nq; j += t) {
        const bool lit_from_above = !first && (buffers.live(b ^ 1, j + g.oq) || buffers.live(b ^ 1, j + g.oq + 1));
        if (!lit_from_above && !stored(s, j)) {
          buffers.clear_row(b, j);
          continue;
        }
        float* f = buffers.density(b, j);
        float* d = buffers.depth(b, j);
        gather(s, j, f);
        sweep_row(g, first, f, d, buffers.depth(b ^ 1, j + g.oq), buffers.depth(b ^ 1, j + g.oq + 1),
                  buffers.density(b ^ 1, j + g.oq), buffers.density(b ^ 1, j + g.oq + 1));
        buffers.note_row(b, j);
        scatter(s, j, static_cast<const float*>(d), static_cast<const float*>(f));
      }
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
}

// Where voxel (p = 0, q = j, a = s) and the step along p lie in the dense layout.
struct DenseRow {
  size_t start, step;
};
DenseRow dense_row(const SweepGeometry& g, int s, int j) {
  size_t stride[3] = {1, size_t(g.n[0]), size_t(g.n[0]) * g.n[1]};
  return {size_t(s) * stride[g.a] + size_t(j) * stride[g.q], stride[g.p]};
}

// Calls f(slot, first voxel in the brick, count) for each run of row (s, j) that lies in one brick
// (slot -1: absent), the runs in order along p; the voxels of a run are `step` apart in the brick.
template <class F>
void for_each_brick_run(const SparseGrid& grid, const SweepGeometry& g, int s, int j, F&& f) {
  constexpr int kSide = SparseGrid::kBrickSide;
  int c[3];
  c[g.a] = s;
  c[g.q] = j;
  for (int i0 = 0; i0 < g.n[g.p]; i0 += kSide) {
    c[g.p] = i0;
    const int32_t slot = grid.slot(c[0] / kSide, c[1] / kSide, c[2] / kSide);
    f(slot, SparseGrid::in_brick(c[0], c[1], c[2]), i0, std::min(kSide, g.n[g.p] - i0));
  }
}

int brick_step(int axis) { return axis == 0 ? 1 : axis == 1 ? SparseGrid::kBrickSide : SparseGrid::kBrickSide * SparseGrid::kBrickSide; }

}  // namespace

std::vector<float> light_optical_depth_sweep(const DenseGrid& grid, const VolumeMedium& medium,
                                             int threads) {
  std::vector<float> depth(grid.values.size(), 0.0f);
  if (grid.empty()) return depth;
  const SweepGeometry g = sweep_geometry(grid, medium);
  const int np = g.n[g.p];
  sweep_slices(
      g, threads,
      [&](int s, int j, float* row) {
        const DenseRow r = dense_row(g, s, j);
        for (int i = 0; i < np; ++i) row[i] = grid.values[r.start + size_t(i) * r.step];
      },
      [&](int s, int j, const float* d, const float*) {
        const DenseRow r = dense_row(g, s, j);
        for (int i = 0; i < np; ++i) depth[r.start + size_t(i) * r.step] = d[i];
      },
      [](int, int) { return true; });
  return depth;
}

std::vector<float> light_transmittance_sweep(const SparseGrid& grid, const VolumeMedium& medium,
                                             int threads) {
  std::vector<float> lit(grid.values.size(), 1.0f);
  if (grid.empty()) return lit;
  const SweepGeometry g = sweep_geometry(grid, medium);
  const int step = brick_step(g.p);
  sweep_slices(
      g, threads,
      [&](int s, int j, float* row) {
        for_each_brick_run(grid, g, s, j, [&](int32_t slot, int at, int i0, int count) {
          if (slot < 0) {
            std::fill(row + i0, row + i0 + count, 0.0f);
            return;
          }
          const float* v = grid.brick(slot) + at;
          for (int i = 0; i < count; ++i) row[i0 + i] = v[i * step];
        });
      },
      [&](int s, int j, const float* d, const float* f) {
        for_each_brick_run(grid, g, s, j, [&](int32_t slot, int at, int i0, int count) {
          if (slot < 0) return;
          float* out = lit.data() + size_t(slot) * SparseGrid::kBrickVoxels + at;
          for (int i = 0; i < count; ++i)
            out[i * step] = f[i0 + i] != 0.0f ? std::exp(-d[i0 + i]) : 1.0f;
        });
      },
      [&](int s, int j) {
        bool any = false;
        for_each_brick_run(grid, g, s, j, [&](int32_t slot, int, int, int) { any = any || slot >= 0; });
        return any;
      });
  return lit;
}

}  // namespace pyro
