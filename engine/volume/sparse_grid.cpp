#include "engine/volume/sparse_grid.h"

#include <algorithm>
#include <cstring>

namespace pyro {

namespace {

constexpr int kSide = SparseGrid::kBrickSide;

// Calls f(bx, by, bz, x0, y0, z0, nx, ny, nz) for every brick of the box: its brick coordinates,
// its first voxel and how many of its voxels lie in the box along each axis.
template <class F>
void for_each_brick(const GridHeader& g, const std::array<int, 3>& bd, F&& f) {
  for (int bz = 0; bz < bd[2]; ++bz)
    for (int by = 0; by < bd[1]; ++by)
      for (int bx = 0; bx < bd[0]; ++bx) {
        const int x0 = bx * kSide, y0 = by * kSide, z0 = bz * kSide;
        f(bx, by, bz, x0, y0, z0, std::min(kSide, g.dims[0] - x0), std::min(kSide, g.dims[1] - y0),
          std::min(kSide, g.dims[2] - z0));
      }
}

}  // namespace

std::array<int, 3> brick_dims_for(const std::array<int, 3>& dims) {
  std::array<int, 3> bd{0, 0, 0};
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0) return bd;
  for (int a = 0; a < 3; ++a) bd[a] = int((int64_t(dims[a]) + kSide - 1) / kSide);
  return bd;
}

uint64_t box_bricks(const std::array<int, 3>& bd) {
  for (int d : bd)
    if (d <= 0) return 0;
  return uint64_t(bd[0]) * uint64_t(bd[1]) * uint64_t(bd[2]);
}

SparseGrid sparse_from_dense(const DenseGrid& grid) {
  SparseGrid s;
  static_cast<GridHeader&>(s) = grid;
  s.brick_dims = brick_dims_for(grid.dims);
  s.slots.assign(box_bricks(s.brick_dims), -1);
  if (grid.empty()) return s;
  const size_t nx = size_t(grid.dims[0]), ny = size_t(grid.dims[1]);
  int32_t next = 0;
  size_t k = 0;
  for_each_brick(grid, s.brick_dims, [&](int, int, int, int x0, int y0, int z0, int cx, int cy, int cz) {
    bool any = false;
    for (int z = 0; z < cz && !any; ++z)
      for (int y = 0; y < cy && !any; ++y) {
        const float* row = &grid.values[((z0 + z) * ny + (y0 + y)) * nx + x0];
        for (int x = 0; x < cx; ++x) {
          uint32_t bits;
          std::memcpy(&bits, row + x, sizeof bits);
          any = any || bits != 0;
        }
      }
    if (any) {
      s.slots[k] = next++;
      s.values.resize(size_t(next) * SparseGrid::kBrickVoxels, 0.0f);
      float* brick = s.values.data() + size_t(next - 1) * SparseGrid::kBrickVoxels;
      for (int z = 0; z < cz; ++z)
        for (int y = 0; y < cy; ++y)
          std::memcpy(brick + SparseGrid::in_brick(0, y, z), &grid.values[((z0 + z) * ny + (y0 + y)) * nx + x0],
                      size_t(cx) * sizeof(float));
    }
    ++k;
  });
  return s;
}

DenseGrid dense_from_sparse(const SparseGrid& grid) {
  DenseGrid d;
  static_cast<GridHeader&>(d) = grid;
  if (grid.empty()) {
    d.dims = {0, 0, 0};
    return d;
  }
  d.values.assign(grid.box_voxels(), 0.0f);
  const size_t nx = size_t(grid.dims[0]), ny = size_t(grid.dims[1]);
  size_t k = 0;
  for_each_brick(grid, grid.brick_dims, [&](int, int, int, int x0, int y0, int z0, int cx, int cy, int cz) {
    const int32_t slot = grid.slots[k++];
    if (slot < 0) return;
    const float* brick = grid.brick(slot);
    for (int z = 0; z < cz; ++z)
      for (int y = 0; y < cy; ++y)
        std::memcpy(&d.values[((z0 + z) * ny + (y0 + y)) * nx + x0], brick + SparseGrid::in_brick(0, y, z),
                    size_t(cx) * sizeof(float));
  });
  return d;
}

}  // namespace pyro
