// The VDB reader's sparse form (read_vdb_grid_sparse): a file written here comes back voxel for
// voxel in bricks aligned to its active box (negative origins, sides not multiples of 8); active
// tiles become bricks (the shared level set, when ../shared/data/vdb is there); a file resampled
// leaf by leaf (vdb_resampled_volume.h) holds the trilinear values it was made of; and a grid
// whose box is too large for a dense copy reads sparse with a few bricks.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/core/user_error.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_resampled_volume.h"
#include "systems/runtime/reference/grid_sampling.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// Random values in (0, 1) over `dims`, with a hole of zeros, non-zero at two opposite corners
// (so that the active box is the whole of dims).
std::vector<float> holey_values(const std::array<int, 3>& dims, uint64_t seed) {
  std::vector<float> v(static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x, ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        const bool hole = x > 3 && x < 20 && y > 2 && z > 2;
        v[i] = hole ? 0.0f : float(double(seed >> 40) / double(1 << 24)) * 0.9f + 0.05f;
      }
  return v;
}

TEST(VdbSparseReader, ReadsEveryVoxelIntoBricksOfTheActiveBox) {
  const fs::path dir = test::scratch_dir("vdb_sparse_roundtrip");
  const std::string path = (dir / "holey.vdb").string();
  const std::array<int, 3> origin{-13, 5, -29}, dims{37, 29, 23};
  const std::vector<float> v = holey_values(dims, 11);
  write_vdb_fog_volume(path, "density", origin, dims, v, 0.25, {1.0, 2.0, 3.0});
  const SparseGrid s = read_vdb_grid_sparse(path);
  EXPECT_EQ(s.origin, origin);
  EXPECT_EQ(s.dims, dims);
  EXPECT_EQ(s.brick_dims, (std::array<int, 3>{5, 4, 3}));
  size_t i = 0, active = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x, ++i) {
        ASSERT_EQ(s.at(x, y, z), v[i]) << x << " " << y << " " << z;
        active += v[i] != 0.0f;
      }
  EXPECT_EQ(s.active_voxels, active);
  // Bricks are counted from the box's corner: those wholly inside the hole are not stored.
  EXPECT_LT(s.bricks(), 5u * 4u * 3u);
  EXPECT_EQ(s.slot(1, 1, 1), -1);  // voxels (8..15, 8..15, 8..15): all in the hole
  // The dense copy is the same grid.
  const DenseGrid d = read_vdb_grid(path);
  EXPECT_EQ(d.values, v);
  EXPECT_EQ(d.max_value, s.max_value);
}

TEST(VdbSparseReader, ActiveTilesOfALevelSetBecomeBricks) {
  if (!fs::is_directory(fs::path(PYRO_SHARED_DATA_DIR) / "vdb"))
    GTEST_SKIP() << "no third-party VDB files at " PYRO_SHARED_DATA_DIR "/vdb (optional data)";
  const SparseGrid s =
      read_vdb_grid_sparse((fs::path(PYRO_SHARED_DATA_DIR) / "vdb" / "openvdb_sample_sphere_levelset.vdb").string());
  EXPECT_TRUE(s.converted_from_level_set);
  // The sphere's inside is tiles of 1 after sdfToFogVolume: the centre, far from any leaf.
  EXPECT_EQ(s.at(s.dims[0] / 2, s.dims[1] / 2, s.dims[2] / 2), 1.0f);
  EXPECT_GE(s.bricks() * SparseGrid::kBrickVoxels, s.active_voxels);
}

TEST(VdbSparseReader, AResampledFileHoldsTheTrilinearValuesOfItsSource) {
  DenseGrid src;
  src.origin = {-3, 2, 7};
  src.dims = {6, 5, 4};
  src.values = holey_values(src.dims, 5);
  src.index_to_world = glm::dmat4(0.5);
  src.index_to_world[3] = glm::dvec4(1.0, -2.0, 0.5, 1.0);
  const double scale = 2.5;
  const fs::path dir = test::scratch_dir("vdb_resampled");
  const std::string path = (dir / "fine.vdb").string();
  const VdbResampleReport report = write_vdb_resampled_fog_volume(path, "density", src, scale);
  const SparseGrid fine = read_vdb_grid_sparse(path);
  EXPECT_EQ(fine.active_voxels, report.active_voxels);
  EXPECT_GT(report.file_bytes, 0u);
  const int n[3] = {src.dims[0], src.dims[1], src.dims[2]};
  uint64_t nonzero = 0;
  for (int z = 0; z < fine.dims[2]; ++z)
    for (int y = 0; y < fine.dims[1]; ++y)
      for (int x = 0; x < fine.dims[0]; ++x) {
        // Fine index I lies at source index (I + 1/2) / scale - 1/2.
        double u[3];
        const int c[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) u[a] = (fine.origin[a] + c[a] + 0.5) / scale - 0.5 - src.origin[a];
        const float want = sample_trilinear(src.values.data(), n, u[0], u[1], u[2]);
        ASSERT_NEAR(fine.at(x, y, z), want, 1e-6) << x << " " << y << " " << z;
        nonzero += fine.at(x, y, z) != 0.0f;
      }
  EXPECT_EQ(nonzero, fine.active_voxels);
  // The fine grid covers the same world: fine voxel I's centre is at the source's index (I + 1/2) / scale - 1/2.
  const glm::dvec4 fine_world = fine.index_to_world * glm::dvec4(fine.origin[0], fine.origin[1], fine.origin[2], 1.0);
  glm::dvec4 src_index(0, 0, 0, 1);
  for (int a = 0; a < 3; ++a) src_index[a] = (fine.origin[a] + 0.5) / scale - 0.5;
  const glm::dvec4 src_world = src.index_to_world * src_index;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(fine_world[a], src_world[a], 1e-9);
}

TEST(VdbSparseReader, ABoxTooLargeForADenseCopyReadsSparse) {
  // Two voxels 139,999 apart, resampled 8 times finer: two clumps of 16^3 voxels in a box of
  // about 1.12e6 x 16 x 16 = 2.9e8 voxels, over the dense copy's 2^28.
  DenseGrid src;
  src.dims = {140000, 1, 1};
  src.values.assign(140000, 0.0f);
  src.values.front() = src.values.back() = 0.5f;
  const fs::path dir = test::scratch_dir("vdb_sparse_large_box");
  const std::string path = (dir / "far.vdb").string();
  write_vdb_resampled_fog_volume(path, "density", src, 8.0);
  try {
    read_vdb_grid(path);
    ADD_FAILURE() << "a dense copy of a 2.9e8-voxel box was made";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("2^28"), std::string::npos) << e.what();
  }
  const SparseGrid s = read_vdb_grid_sparse(path);
  EXPECT_GT(s.box_voxels(), uint64_t{1} << 28);
  EXPECT_EQ(s.active_voxels, 2u * 16u * 16u * 16u);
  EXPECT_LE(s.bricks(), 2u * 27u);  // each clump meets at most 3 x 3 x 3 bricks
  EXPECT_EQ(s.at(s.dims[0] - 8, 8, 8), s.at(7, 8, 8));  // the two clumps alike
  EXPECT_GT(s.at(7, 8, 8), 0.0f);
}

}  // namespace
}  // namespace pyro
