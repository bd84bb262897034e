#include "systems/cloud_import/light_sweep.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "systems/reference/volume_reference.h"

namespace pyro {

std::vector<float> light_optical_depth_sweep(const DenseGrid& grid, const VolumeMedium& medium) {
  std::vector<float> depth(grid.values.size(), 0.0f);
  if (grid.empty()) return depth;
  const glm::dmat3 to_index(world_to_local_index(grid));
  const glm::dvec3 u = to_index * -glm::normalize(medium.light_direction);  // index per world unit
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(u[k]) > std::abs(u[a])) a = k;
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const double ua = std::abs(u[a]);
  const double world_step = 1.0 / ua;                 // world length of one slice step
  const double vb = u[b] / ua, vc = u[c] / ua;        // in-slice offset of the upstream point
  const int sa = u[a] > 0 ? 1 : -1;                   // the light lies towards +a when sa = 1
  const int n[3] = {grid.dims[0], grid.dims[1], grid.dims[2]};
  const size_t stride[3] = {1, size_t(n[0]), size_t(n[0]) * n[1]};
  const float* f = grid.values.data();
  const float step_tau = float(0.5 * world_step * medium.extinction);
  const int first = sa > 0 ? n[a] - 1 : 0;
  // Bilinear weights are the same for every voxel: the offset (vb, vc) is constant.
  const int ob = int(std::floor(vb)), oc = int(std::floor(vc));
  const float tb = float(vb - ob), tc = float(vc - oc);
  for (int s = first; s >= 0 && s < n[a]; s -= sa) {
    const int up = s + sa;  // the slice towards the light
    const bool inside = up >= 0 && up < n[a];
    for (int j = 0; j < n[c]; ++j)
      for (int i = 0; i < n[b]; ++i) {
        const size_t here = size_t(s) * stride[a] + size_t(i) * stride[b] + size_t(j) * stride[c];
        float tau_up = 0.0f, rho_up = 0.0f;
        if (inside) {
          const auto corner = [&](int di, int dj, float& t, float& r) {
            const int ii = i + ob + di, jj = j + oc + dj;
            if (ii < 0 || jj < 0 || ii >= n[b] || jj >= n[c]) {
              t = 0.0f;
              r = 0.0f;
              return;
            }
            const size_t q = size_t(up) * stride[a] + size_t(ii) * stride[b] + size_t(jj) * stride[c];
            t = depth[q];
            r = f[q];
          };
          float t00, r00, t10, r10, t01, r01, t11, r11;
          corner(0, 0, t00, r00);
          corner(1, 0, t10, r10);
          corner(0, 1, t01, r01);
          corner(1, 1, t11, r11);
          tau_up = (1 - tc) * ((1 - tb) * t00 + tb * t10) + tc * ((1 - tb) * t01 + tb * t11);
          rho_up = (1 - tc) * ((1 - tb) * r00 + tb * r10) + tc * ((1 - tb) * r01 + tb * r11);
        }
        depth[here] = tau_up + step_tau * (f[here] + rho_up);
      }
  }
  return depth;
}

}  // namespace pyro
