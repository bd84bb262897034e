// The project's fire: deterministic from its seed, laid out as a Mantaflow cache frame (density,
// temperature, velocity), hot at the base and smoky above, and the committed
// content/volumes/sample_fire.vdb is what the generator makes with the defaults (no velocity), saved
// as half floats (`make_sample_volume --fire --half`): equal to 2^-11 relative.
#include "engine/volume/procedural_fire.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/core/content_path.h"
#include "engine/io/vdb_reader.h"

namespace pyro {
namespace {

TEST(ProceduralFire, IsAMantaflowLikeFrameFromTheSeed) {
  const std::vector<VdbGridToWrite> a = make_procedural_fire({}), b = make_procedural_fire({});
  ProceduralFireOptions other;
  other.seed = 2;
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].name, "density");
  EXPECT_EQ(a[1].name, "temperature");
  EXPECT_EQ(a[2].name, "velocity");
  EXPECT_TRUE(a[2].vec3);
  EXPECT_EQ(a[0].values, b[0].values);
  EXPECT_NE(a[0].values, make_procedural_fire(other)[0].values);
  // Heat in the lower third outweighs heat in the upper third; density the other way round.
  const std::array<int, 3> n = a[0].dims;
  double heat_low = 0, heat_high = 0, smoke_low = 0, smoke_high = 0, heat_max = 0;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const size_t k = (size_t(z) * n[1] + y) * n[0] + x;
        if (y < n[1] / 3) heat_low += a[1].values[k], smoke_low += a[0].values[k];
        if (y >= 2 * n[1] / 3) heat_high += a[1].values[k], smoke_high += a[0].values[k];
        heat_max = std::max(heat_max, double(a[1].values[k]));
      }
  EXPECT_GT(heat_low, 4.0 * heat_high);
  EXPECT_GT(smoke_high, smoke_low);
  EXPECT_GT(heat_max, 0.5);
  EXPECT_LE(heat_max, 1.0);  // normalised, as Mantaflow stores heat
}

TEST(ProceduralFire, TheCommittedSampleIsTheGeneratorsOutput) {
  ProceduralFireOptions o;
  o.velocity = false;
  const std::vector<VdbGridToWrite> made = make_procedural_fire(o);
  const std::string path = content_path("volumes/sample_fire.vdb");
  const std::vector<VdbGridInfo> grids = list_vdb_grids(path);
  ASSERT_EQ(grids.size(), 2u);
  for (int g = 0; g < 2; ++g) {
    VdbGridChoice choice;
    choice.index = g;
    const DenseGrid read = read_vdb_grid(path, choice);
    EXPECT_EQ(read.name, made[size_t(g)].name);
    const VdbGridToWrite& m = made[size_t(g)];
    size_t k = 0;
    for (int z = 0; z < m.dims[2]; ++z)
      for (int y = 0; y < m.dims[1]; ++y)
        for (int x = 0; x < m.dims[0]; ++x, ++k) {
          const int rx = m.origin[0] + x - read.origin[0], ry = m.origin[1] + y - read.origin[1],
                    rz = m.origin[2] + z - read.origin[2];
          const bool inside = rx >= 0 && ry >= 0 && rz >= 0 && rx < read.dims[0] && ry < read.dims[1] && rz < read.dims[2];
          const float got = inside ? read.at(rx, ry, rz) : 0.0f;
          ASSERT_NEAR(got, m.values[k], std::ldexp(std::abs(m.values[k]), -11)) << m.name << " " << x << " " << y << " " << z;
        }
  }
}

}  // namespace
}  // namespace pyro
