#include "systems/cloud_import/light_sweep.h"

#include <algorithm>
#include <barrier>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "systems/reference/volume_reference.h"

namespace pyro {

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
  const glm::dmat3 to_index(world_to_local_index(grid));
  const glm::dvec3 u = to_index * -glm::normalize(medium.light_direction);  // index per world unit
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(u[k]) > std::abs(u[a])) a = k;
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  const size_t stride[3] = {1, size_t(n[0]), size_t(n[0]) * n[1]};
  // In-slice axes: p innermost (smaller stride), q outer.
  int p = (a + 1) % 3, q = (a + 2) % 3;
  if (stride[p] > stride[q]) std::swap(p, q);
  const double ua = std::abs(u[a]);
  const double world_step = 1.0 / ua;             // world length of one slice step
  const double vp = u[p] / ua, vq = u[q] / ua;    // in-slice offset of the upstream point, |v| <= 1
  const int sa = u[a] > 0 ? 1 : -1;               // the light lies towards +a when sa = 1
  const float* f = grid.values.data();
  float* d = depth.data();
  const float step_tau = float(0.5 * world_step * medium.extinction);
  const int first = sa > 0 ? n[a] - 1 : 0;
  // Bilinear weights are the same for every voxel: the offset (vp, vq) is constant.
  const int op = int(std::floor(vp)), oq = int(std::floor(vq));  // each in {-1, 0, 1}
  const float tp = float(vp - op), tq = float(vq - oq);
  const int np = n[p], nq = n[q];
  constexpr int kPad = 2;

  int t = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
  t = std::max(1, std::min(t, nq));
  std::barrier sync(t);
  const auto work = [&](int k) {
    // Upstream rows q + oq and q + oq + 1, zero-padded by kPad on both sides.
    std::vector<float> t0(np + 2 * kPad), t1(np + 2 * kPad), r0(np + 2 * kPad), r1(np + 2 * kPad);
    const auto load = [&](int up, int row, std::vector<float>& tau, std::vector<float>& rho) {
      if (row < 0 || row >= nq) {
        std::fill(tau.begin(), tau.end(), 0.0f);
        std::fill(rho.begin(), rho.end(), 0.0f);
        return;
      }
      const size_t base = size_t(up) * stride[a] + size_t(row) * stride[q];
      for (int i = 0; i < np; ++i) {
        tau[kPad + i] = d[base + size_t(i) * stride[p]];
        rho[kPad + i] = f[base + size_t(i) * stride[p]];
      }
    };
    for (int s = first; s >= 0 && s < n[a]; s -= sa) {
      const int up = s + sa;  // the slice towards the light
      const bool inside = up >= 0 && up < n[a];
      for (int j = k; j < nq; j += t) {
        const size_t row = size_t(s) * stride[a] + size_t(j) * stride[q];
        if (!inside) {
          for (int i = 0; i < np; ++i) {
            const size_t here = row + size_t(i) * stride[p];
            d[here] = step_tau * f[here];
          }
          continue;
        }
        load(up, j + oq, t0, r0);
        load(up, j + oq + 1, t1, r1);
        const float* a0 = t0.data() + kPad + op;
        const float* a1 = t1.data() + kPad + op;
        const float* b0 = r0.data() + kPad + op;
        const float* b1 = r1.data() + kPad + op;
        for (int i = 0; i < np; ++i) {
          const float tau_up = (1 - tq) * ((1 - tp) * a0[i] + tp * a0[i + 1]) +
                               tq * ((1 - tp) * a1[i] + tp * a1[i + 1]);
          const float rho_up = (1 - tq) * ((1 - tp) * b0[i] + tp * b0[i + 1]) +
                               tq * ((1 - tp) * b1[i] + tp * b1[i + 1]);
          const size_t here = row + size_t(i) * stride[p];
          d[here] = tau_up + step_tau * (f[here] + rho_up);
        }
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
  return depth;
}

}  // namespace pyro
