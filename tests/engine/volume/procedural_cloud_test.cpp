// The sample cloud: deterministic from its seed, a few tens of thousands of active voxels, and the
// committed content/volumes/sample_cloud.vdb is exactly what the generator makes with the defaults.
#include "engine/volume/procedural_cloud.h"

#include <gtest/gtest.h>

#include "engine/core/content_path.h"
#include "engine/io/vdb_reader.h"

namespace pyro {
namespace {

TEST(ProceduralCloud, IsDeterministicFromTheSeed) {
  const DenseGrid a = make_procedural_cloud({});
  const DenseGrid b = make_procedural_cloud({});
  ProceduralCloudOptions other;
  other.seed = 2;
  const DenseGrid c = make_procedural_cloud(other);
  EXPECT_EQ(a.values, b.values);
  EXPECT_NE(a.values, c.values);
  EXPECT_GE(a.active_voxels, 20000u);
  EXPECT_LE(a.active_voxels, 100000u);
  EXPECT_GT(a.max_value, 0.9f);
  EXPECT_LE(a.max_value, 1.0f);
}

TEST(ProceduralCloud, TheCommittedSampleIsTheGeneratorsOutput) {
  const DenseGrid made = make_procedural_cloud({});
  const DenseGrid read = read_vdb_grid(content_path("volumes/sample_cloud.vdb"));
  EXPECT_EQ(read.name, "density");
  EXPECT_EQ(read.active_voxels, made.active_voxels);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(read.index_to_world[r][c], made.index_to_world[r][c], 1e-12);
  // The read grid covers the active bounding box; every made value must sit at its index there.
  uint64_t compared = 0;
  for (int z = 0; z < made.dims[2]; ++z)
    for (int y = 0; y < made.dims[1]; ++y)
      for (int x = 0; x < made.dims[0]; ++x) {
        const float v = made.at(x, y, z);
        const int rx = x - read.origin[0], ry = y - read.origin[1], rz = z - read.origin[2];
        const bool inside = rx >= 0 && ry >= 0 && rz >= 0 && rx < read.dims[0] && ry < read.dims[1] &&
                            rz < read.dims[2];
        if (!inside) {
          ASSERT_EQ(v, 0.0f) << x << " " << y << " " << z;
          continue;
        }
        ASSERT_EQ(read.at(rx, ry, rz), v) << x << " " << y << " " << z;
        ++compared;
      }
  EXPECT_EQ(compared, read.size());
}

}  // namespace
}  // namespace pyro
