// The sparse grid against the dense grid it is made from: every voxel comes back bit for bit,
// whatever the box (sides not multiples of 8, one voxel thick), only bricks holding a value are
// stored, and at() is 0 outside them and outside the box.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "engine/volume/sparse_grid.h"

namespace pyro {
namespace {

// Values in [0, 1) with about `empty` of them 0 and whole regions of zeros (x < dims[0] / 3).
DenseGrid patchy_grid(const std::array<int, 3>& dims, uint64_t seed, double empty) {
  DenseGrid g;
  g.origin = {-13, 5, -29};
  g.dims = dims;
  g.values.assign(g.box_voxels(), 0.0f);
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x, ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        const double r = double(seed >> 11) / double(uint64_t{1} << 53);
        if (x >= dims[0] / 3 && r >= empty) g.values[i] = float(r);
      }
  return g;
}

TEST(SparseGrid, RoundTripsDenseGridsBitForBit) {
  for (const std::array<int, 3>& dims : {std::array<int, 3>{37, 29, 23}, std::array<int, 3>{8, 16, 24},
                                         std::array<int, 3>{1, 1, 1}, std::array<int, 3>{1, 40, 3}}) {
    DenseGrid g = patchy_grid(dims, 7, 0.5);
    g.values[0] = -0.0f;  // a negative zero is a value too
    const SparseGrid s = sparse_from_dense(g);
    EXPECT_EQ(s.brick_dims, (std::array<int, 3>{(dims[0] + 7) / 8, (dims[1] + 7) / 8, (dims[2] + 7) / 8}));
    EXPECT_EQ(s.origin, g.origin);
    const DenseGrid back = dense_from_sparse(s);
    ASSERT_EQ(back.values.size(), g.values.size());
    EXPECT_EQ(std::memcmp(back.values.data(), g.values.data(), g.values.size() * sizeof(float)), 0);
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) ASSERT_EQ(s.at(x, y, z), g.at(x, y, z)) << x << " " << y << " " << z;
  }
}

TEST(SparseGrid, StoresOnlyBricksHoldingAValue) {
  DenseGrid g = patchy_grid({40, 16, 16}, 3, 2.0);  // all 0
  g.values[(size_t(9) * 16 + 3) * 40 + 33] = 0.5f;   // one voxel, in brick (4, 0, 1)
  const SparseGrid s = sparse_from_dense(g);
  EXPECT_EQ(s.bricks(), 1u);
  EXPECT_EQ(s.values.size(), size_t(SparseGrid::kBrickVoxels));
  EXPECT_EQ(s.slot(4, 0, 1), 0);
  EXPECT_EQ(s.slot(3, 0, 1), -1);
  EXPECT_EQ(s.at(33, 3, 9), 0.5f);
  EXPECT_EQ(s.at(32, 3, 9), 0.0f);
  EXPECT_EQ(s.at(-1, 3, 9), 0.0f);   // outside the box
  EXPECT_EQ(s.at(33, 3, 99), 0.0f);
}

TEST(SparseGrid, AnEmptyGridHasNoBricks) {
  const SparseGrid s = sparse_from_dense(DenseGrid{});
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.bricks(), 0u);
  EXPECT_TRUE(dense_from_sparse(s).empty());
}

}  // namespace
}  // namespace pyro
