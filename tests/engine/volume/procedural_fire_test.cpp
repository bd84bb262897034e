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

// A buoyant plume widens as it rises and stays clear of the box's sides: no density on the four
// side faces, and the smoke's spread about its own axis (the density-weighted RMS distance from
// each layer's centroid) in the top fifth is at least 1.15 times that at mid-height.
TEST(ProceduralFire, TheSmokeIsAPlumeThatWidensAsItRisesClearOfTheSides) {
  const VdbGridToWrite density = make_procedural_fire()[0];
  const std::array<int, 3> n = density.dims;
  const auto at = [&](int x, int y, int z) { return double(density.values[(size_t(z) * n[1] + y) * n[0] + x]); };
  int on_sides = 0;
  for (int y = 0; y < n[1]; ++y)
    for (int i = 0; i < n[0]; ++i)
      on_sides += (at(0, y, i) > 0.0) + (at(n[0] - 1, y, i) > 0.0) + (at(i, y, 0) > 0.0) + (at(i, y, n[2] - 1) > 0.0);
  EXPECT_EQ(on_sides, 0);
  // The mean over layers [y0, y1) of each layer's RMS distance from its centroid.
  const auto spread = [&](int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y) {
      double m = 0.0, cx = 0.0, cz = 0.0, r2 = 0.0;
      for (int z = 0; z < n[2]; ++z)
        for (int x = 0; x < n[0]; ++x) m += at(x, y, z), cx += x * at(x, y, z), cz += z * at(x, y, z);
      cx /= m;
      cz /= m;
      for (int z = 0; z < n[2]; ++z)
        for (int x = 0; x < n[0]; ++x) r2 += ((x - cx) * (x - cx) + (z - cz) * (z - cz)) * at(x, y, z);
      sum += std::sqrt(r2 / m);
    }
    return sum / (y1 - y0);
  };
  const double middle = spread(n[1] * 9 / 20, n[1] * 11 / 20), top = spread(n[1] * 3 / 4, n[1] * 19 / 20);
  EXPECT_GT(top, 1.15 * middle) << "mid-height " << middle << ", top " << top;
}

TEST(ProceduralFire, TheCalibrationBoxIsOneTemperatureInsideTwoEmptyVoxels) {
  const std::vector<VdbGridToWrite> g = make_uniform_fire_box(1750.0);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].name, "density");
  EXPECT_EQ(g[1].name, "temperature");
  size_t inside = 0;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const size_t i = (size_t(z) * 16 + y) * 16 + x;
        const bool in = x >= 2 && x < 14 && y >= 2 && y < 14 && z >= 2 && z < 14;
        EXPECT_EQ(g[0].values[i], in ? 1.0f : 0.0f);
        EXPECT_EQ(g[1].values[i], in ? 1750.0f : 0.0f);
        inside += in;
      }
  EXPECT_EQ(inside, 12u * 12u * 12u);
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
