#pragma once
// A float grid stored sparsely: the active bounding box (grid_header.h) cut into bricks of 8^3
// voxels, OpenVDB's leaf size, of which only those holding a value are stored, one after another;
// a coarse table over the box, one entry per brick, says where each one is (or that it is absent,
// all 0). Memory: 2 KiB per stored brick plus 4 bytes per 512 voxels of the box, so it grows with
// the active voxels, not with the box. at(x, y, z) is O(1).
//
// Bricks are aligned to the box's low corner (local coordinate 0), not to OpenVDB's leaves
// (index coordinates that are multiples of 8): the importer's blocks are aligned to the same
// corner (systems/runtime/cloud_import/cloud_import.h), so a brick is exactly one of its 8^3 blocks and
// the block statistics below it live inside the brick.
#include <cstdint>
#include <vector>

#include "engine/volume/dense_grid.h"
#include "engine/volume/grid_header.h"

namespace pyro {

struct SparseGrid : GridHeader {
  static constexpr int kBrickShift = 3;
  static constexpr int kBrickSide = 1 << kBrickShift;  // 8
  static constexpr int kBrickVoxels = kBrickSide * kBrickSide * kBrickSide;
  // The largest box the coarse table may cover, in bricks (1 GiB of table; 2^37 voxels).
  static constexpr uint64_t kMaxBoxBricks = uint64_t{1} << 28;

  std::array<int, 3> brick_dims{0, 0, 0};  // the box in bricks: ceil(dims / 8)
  // Per brick of the box, x fastest ((bz * brick_dims[1] + by) * brick_dims[0] + bx): the
  // brick's slot in `values`, or -1 when it is absent (all its voxels 0).
  std::vector<int32_t> slots;
  // Slot after slot, kBrickVoxels floats each; within a brick x fastest (in_brick). Voxels of a
  // brick that lie past the box hold 0.
  std::vector<float> values;

  bool empty() const { return box_voxels() == 0; }
  size_t bricks() const { return values.size() / kBrickVoxels; }
  // The slot of brick (bx, by, bz), -1 when absent or outside the box.
  int32_t slot(int bx, int by, int bz) const {
    if (bx < 0 || by < 0 || bz < 0 || bx >= brick_dims[0] || by >= brick_dims[1] || bz >= brick_dims[2])
      return -1;
    return slots[(size_t(bz) * brick_dims[1] + size_t(by)) * brick_dims[0] + size_t(bx)];
  }
  const float* brick(int32_t slot) const { return values.data() + size_t(slot) * kBrickVoxels; }
  static int in_brick(int x, int y, int z) {
    const int m = kBrickSide - 1;
    return (((z & m) << kBrickShift) + (y & m)) * kBrickSide + (x & m);
  }
  // The value at local coordinate (x, y, z); 0 outside the stored bricks.
  float at(int x, int y, int z) const {
    const int32_t s = slot(x >> kBrickShift, y >> kBrickShift, z >> kBrickShift);
    return s < 0 ? 0.0f : brick(s)[in_brick(x, y, z)];
  }
};

// The box in bricks, ceil(dims / 8) on each axis, and its number of bricks (0 for an empty box).
std::array<int, 3> brick_dims_for(const std::array<int, 3>& dims);
uint64_t box_bricks(const std::array<int, 3>& brick_dims);

// The same grid, sparse: the bricks holding any value whose bits are not all 0 are kept (so the
// dense grid comes back bit for bit), slots in the table's order.
SparseGrid sparse_from_dense(const DenseGrid& grid);
// The same grid, dense over its box. The caller decides whether the box is small enough.
DenseGrid dense_from_sparse(const SparseGrid& grid);

}  // namespace pyro
