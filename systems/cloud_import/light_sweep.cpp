#include "systems/cloud_import/light_sweep.h"

#include <algorithm>
#include <barrier>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "systems/reference/volume_reference.h"

namespace pyro {

namespace {

constexpr int kPad = 2;

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

SweepGeometry sweep_geometry(const DenseGrid& grid, const VolumeMedium& medium) {
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

void load_upstream_row(const SweepGeometry& g, const float* f, const float* d, int up, int row,
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
void sweep_row(const SweepGeometry& g, const float* f, float* d, int s, int j, UpstreamRows& up_rows) {
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

}  // namespace

// Speed (the Disney cloud's 1.67 M dense voxels): the slice's two in-slice axes are walked with
// the one of smaller stride innermost (x whenever x is not the sweep axis), the two upstream rows
// are first copied into zero-padded buffers so the bilinear lookups need no bounds checks, and the
// rows of a slice are shared among threads that meet at a barrier between slices. Every voxel's
// value is computed by the same expression from the same inputs whoever computes it, so the result
// does not depend on the thread count (tested).
std::vector<float> light_optical_depth_sweep(const DenseGrid& grid, const VolumeMedium& medium,
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

}  // namespace pyro
