// The importer reads sparse grids (engine/volume/sparse_grid.h) and gives, bit for bit and in the
// same order, the particles of the dense importer it replaced (dense_import_oracle.h): on grids
// whose box is not a multiple of 8 or 16, with negative origins, empty regions, one voxel thick,
// for every sweep axis, pyramid depth, tolerance (0 included) and thread count; on the project's
// sample cloud and, when present, the shared files read sparse from disk; and a clump in a box
// too large for a dense copy imports as it does alone.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "engine/io/vdb_reader.h"
#include "engine/volume/procedural_cloud.h"
#include "systems/runtime/cloud_import/cloud_import.h"
#include "systems/runtime/cloud_import/grid_framing.h"
#include "tests/systems/runtime/cloud_import/dense_import_oracle.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

bool same_particles(const std::vector<GaussianParticle>& a, const std::vector<GaussianParticle>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0);
}

// Random densities with clumps and empty regions (x in the first third empty), on a skewed
// transform.
DenseGrid patchy_grid_sparse_import(const std::array<int, 3>& origin, const std::array<int, 3>& dims, uint64_t seed) {
  DenseGrid g;
  g.origin = origin;
  g.dims = dims;
  g.values.assign(g.box_voxels(), 0.0f);
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x, ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        const float r = float(seed >> 40) / float(1 << 24);
        if (x >= dims[0] / 3 && r > 0.4f) g.values[i] = r * (1.0f + 0.5f * std::sin(0.3f * float(y + z)));
      }
  g.index_to_world = glm::dmat4(0.5);
  g.index_to_world[1][0] = 0.1;  // a shear
  g.index_to_world[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
  g.active_voxels = 1;
  for (float v : g.values) g.max_value = std::max(g.max_value, v);
  return g;
}

TEST(SparseImport, MatchesTheDenseImporterOnSyntheticGrids) {
  ProceduralCloudOptions cloud;
  cloud.width = 37;
  DenseGrid procedural = make_procedural_cloud(cloud);
  procedural.origin = {-13, 5, -29};
  const std::vector<DenseGrid> grids = {
      patchy_grid_sparse_import({-13, 5, -29}, {37, 29, 23}, 1), patchy_grid_sparse_import({0, 0, 0}, {16, 8, 32}, 2),
      patchy_grid_sparse_import({-8, -8, -8}, {1, 1, 40}, 3), patchy_grid_sparse_import({3, -2, 100}, {17, 3, 50}, 4),
      patchy_grid_sparse_import({0, 0, 0}, {1, 1, 1}, 5), procedural};
  const glm::dvec3 directions[] = {{-0.4, -1.0, -0.3}, {1.0, 0.2, -0.5}, {0.1, 0.3, 1.0}, {0.0, 0.0, -1.0}};
  int compared = 0;
  for (size_t k = 0; k < grids.size(); ++k) {
    const SparseGrid sparse = sparse_from_dense(grids[k]);
    for (const glm::dvec3& dir : directions)
      for (int level : {0, 2, 3, 4, 5}) {
        CloudImportOptions opt;
        opt.medium.extinction = default_extinction(grids[k]);
        opt.medium.light_direction = dir;
        opt.max_level = level;
        opt.tau_tolerance = level == 3 ? 0.0 : level == 5 ? 0.02 : 0.1;
        opt.threads = 1 + (level & 1) * 2;
        const std::vector<GaussianParticle> want = oracle::dense_import(grids[k], opt);
        ASSERT_TRUE(same_particles(import_cloud(sparse, opt), want))
            << "grid " << k << " level " << level << " light " << dir.x << " " << dir.y << " " << dir.z;
        ASSERT_TRUE(same_particles(import_cloud(grids[k], opt), want)) << "dense wrapper, grid " << k;
        compared += !want.empty();
      }
  }
  EXPECT_GT(compared, 100);
}

// Imports `path` as import-vdb does (default medium, the default error target's tolerance) read
// sparse, and compares with the dense importer on the dense copy.
void expect_file_imports_as_before(const std::string& path) {
  const SparseGrid sparse = read_vdb_grid_sparse(path);
  const DenseGrid dense = dense_from_sparse(sparse);
  for (double tolerance : {tau_tolerance_for_error(0.03), tau_tolerance_for_error(0.01)}) {
    CloudImportOptions opt;
    opt.medium = default_medium(dense);
    opt.tau_tolerance = tolerance;
    const std::vector<GaussianParticle> want = oracle::dense_import(dense, opt);
    EXPECT_FALSE(want.empty()) << path;
    EXPECT_TRUE(same_particles(import_cloud(sparse, opt), want)) << path << " tolerance " << tolerance;
  }
}

TEST(SparseImport, MatchesTheDenseImporterOnTheSampleCloud) {
  expect_file_imports_as_before((fs::path(PYRO_SOURCE_DIR) / "content" / "volumes" / "sample_cloud.vdb").string());
}

TEST(SparseImport, MatchesTheDenseImporterOnTheSharedFiles) {
  const fs::path shared = fs::path(PYRO_SHARED_DATA_DIR) / "vdb";
  if (!fs::is_directory(shared)) GTEST_SKIP() << "no third-party VDB files at " << shared << " (optional data)";
  for (const char* name : {"wdas_cloud_sixteenth.vdb", "openvdb_sample_smoke1.vdb",
                           "openvdb_sample_sphere_levelset.vdb", "openusd_smoke_000002.vdb"})
    expect_file_imports_as_before((shared / name).string());
}

// One clump alone, and the same clump at a whole number of top blocks into a box of 3e8 voxels
// (over the dense copy's 2^28) with nothing else: the same particles, in the same order.
TEST(SparseImport, AClumpInABoxTooLargeForADenseCopyImportsAsItDoesAlone) {
  const DenseGrid clump = patchy_grid_sparse_import({100, -40, 7}, {24, 21, 19}, 9);
  CloudImportOptions opt;
  opt.medium.extinction = 0.8;
  opt.medium.light_direction = {-0.4, -1.0, -0.3};
  opt.tau_tolerance = 0.05;
  const std::vector<GaussianParticle> alone = import_cloud(clump, opt);
  ASSERT_FALSE(alone.empty());

  const SparseGrid small = sparse_from_dense(clump);
  SparseGrid big = small;
  const std::array<int, 3> shift{1024, 16, 1536};  // whole top blocks (16 voxels)
  big.dims = {2048, 48, 3072};
  for (int a = 0; a < 3; ++a) big.origin[a] = clump.origin[a] - shift[a];
  ASSERT_GT(big.box_voxels(), uint64_t{1} << 28);
  big.brick_dims = brick_dims_for(big.dims);
  big.slots.assign(box_bricks(big.brick_dims), -1);
  for (int bz = 0; bz < small.brick_dims[2]; ++bz)
    for (int by = 0; by < small.brick_dims[1]; ++by)
      for (int bx = 0; bx < small.brick_dims[0]; ++bx)
        big.slots[(size_t(bz + shift[2] / 8) * big.brick_dims[1] + size_t(by + shift[1] / 8)) * big.brick_dims[0] +
                  size_t(bx + shift[0] / 8)] = small.slot(bx, by, bz);
  EXPECT_TRUE(same_particles(import_cloud(big, opt), alone));
}

}  // namespace
}  // namespace pyro
