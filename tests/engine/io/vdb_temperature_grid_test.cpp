// The temperature grid beside the density: chosen by name or by its usual names, refused clearly,
// and carried into the density's index space. Grids written here with OpenVDB (different voxel
// sizes, per-axis scales and offsets); the resampled values are checked against the closed form
// of a temperature that is linear in world space, which trilinear reconstruction keeps exactly.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "engine/core/user_error.h"
#include "engine/io/vdb_reader.h"
#include "engine/io/vdb_temperature_grid.h"
#include "engine/volume/grid_resample.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// What choose_temperature_grid says when it refuses `name` ("accepted" when it does not).
std::string refusal_vdb_temperature_grid(const std::string& path, const std::vector<VdbGridInfo>& grids, const std::string& name) {
  try {
    choose_temperature_grid(path, grids, name, "--temperature-grid");
  } catch (const UserError& e) {
    return e.what();
  }
  return "accepted";
}

// The temperature at a world point: linear, so trilinear reconstruction is exact.
double linear_temperature(const glm::dvec3& p) { return 300.0 + 40.0 * p.x - 25.0 * p.y + 60.0 * p.z; }

VdbGridToWrite filled(const std::string& name, std::array<int, 3> origin, std::array<int, 3> dims,
                      std::array<double, 3> voxel, std::array<double, 3> shift,
                      const std::function<float(const glm::dvec3&)>& value) {
  VdbGridToWrite g;
  g.name = name;
  g.origin = origin;
  g.dims = dims;
  g.voxel_size = voxel;
  g.translation = shift;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) {
        const glm::dvec3 world((origin[0] + x) * voxel[0] + shift[0], (origin[1] + y) * voxel[1] + shift[1],
                               (origin[2] + z) * voxel[2] + shift[2]);
        g.values.push_back(value(world));
      }
  return g;
}

std::string fire_file(const fs::path& dir) {
  const std::string path = (dir / "fire.vdb").string();
  const VdbGridToWrite density =
      filled("density", {2, 3, 4}, {10, 8, 9}, {0.5, 0.5, 0.5}, {1.0, 2.0, 3.0}, [](const glm::dvec3&) { return 0.5f; });
  // Coarser, non-uniform voxels, another offset, a box reaching past the density's on every side.
  const VdbGridToWrite heat = filled("heat", {-1, 0, 1}, {12, 14, 13}, {0.7, 0.6, 0.8}, {0.3, -0.2, 0.1},
                                     [](const glm::dvec3& p) { return float(linear_temperature(p)); });
  VdbGridToWrite velocity = filled("velocity", {0, 0, 0}, {2, 2, 2}, {0.5, 0.5, 0.5}, {0, 0, 0},
                                   [](const glm::dvec3&) { return 1.0f; });
  velocity.vec3 = true;
  velocity.values.resize(3 * 8, 1.0f);
  write_vdb_grids(path, {density, velocity, heat});
  return path;
}

TEST(VdbTemperatureGrid, ResampledIntoTheDensityIndexSpaceMatchesTheClosedForm) {
  const std::string path = fire_file(test::scratch_dir("vdb_temperature_resample"));
  const DenseGrid density = read_vdb_grid(path);
  const auto chosen = choose_temperature_grid(path, list_vdb_grids(path), "", "--temperature-grid");
  ASSERT_TRUE(chosen.has_value());
  EXPECT_EQ(chosen->name, "heat");
  const DenseGrid heat = read_temperature_grid(path, *chosen, density);
  ASSERT_EQ(heat.dims, density.dims);
  ASSERT_EQ(heat.origin, density.origin);
  int checked = 0;
  for (int z = 0; z < density.dims[2]; ++z)
    for (int y = 0; y < density.dims[1]; ++y)
      for (int x = 0; x < density.dims[0]; ++x) {
        const glm::dvec4 w = density.index_to_world *
                             glm::dvec4(density.origin[0] + x, density.origin[1] + y, density.origin[2] + z, 1.0);
        EXPECT_NEAR(heat.at(x, y, z), linear_temperature(glm::dvec3(w)), 2e-3 * linear_temperature(glm::dvec3(w)))
            << x << " " << y << " " << z;
        ++checked;
      }
  EXPECT_EQ(checked, 10 * 8 * 9);
}

TEST(VdbTemperatureGrid, OutsideTheSourceBoxTheBackgroundFallsToZero) {
  DenseGrid source;
  source.dims = {2, 1, 1};
  source.values = {4.0f, 4.0f};
  EXPECT_DOUBLE_EQ(trilinear_at(source, 0.5, 0.0, 0.0), 4.0);
  EXPECT_DOUBLE_EQ(trilinear_at(source, 1.5, 0.0, 0.0), 2.0);  // half way to the background
  EXPECT_DOUBLE_EQ(trilinear_at(source, 2.5, 0.0, 0.0), 0.0);
}

TEST(VdbTemperatureGrid, DefaultOrderIsTemperatureHeatFlame) {
  std::vector<VdbGridInfo> grids(4);
  grids[0].name = "density";
  grids[1].name = "flame";
  grids[2].name = "heat";
  grids[3].name = "temperature";
  for (VdbGridInfo& g : grids) g.value_type = "float";
  EXPECT_EQ(choose_temperature_grid("f.vdb", grids, "", "--temperature-grid")->name, "temperature");
  grids[3].value_type = "vec3s";  // not a float grid: skipped by the automatic choice
  EXPECT_EQ(choose_temperature_grid("f.vdb", grids, "", "--temperature-grid")->name, "heat");
  EXPECT_EQ(choose_temperature_grid("f.vdb", grids, "flame", "--temperature-grid")->name, "flame");
  EXPECT_FALSE(choose_temperature_grid("f.vdb", grids, "none", "--temperature-grid").has_value());
  grids.resize(1);
  EXPECT_FALSE(choose_temperature_grid("f.vdb", grids, "", "--temperature-grid").has_value());
}

TEST(VdbTemperatureGrid, AbsentOrNonFloatNamedGridsAreRefusedNamingFileOptionAndGrids) {
  const std::string path = fire_file(test::scratch_dir("vdb_temperature_refused"));
  const auto grids = list_vdb_grids(path);
  const std::string absent = refusal_vdb_temperature_grid(path, grids, "fuel");
  EXPECT_NE(absent.find(path), std::string::npos) << absent;
  EXPECT_NE(absent.find("--temperature-grid"), std::string::npos) << absent;
  EXPECT_NE(absent.find("\"fuel\""), std::string::npos) << absent;
  EXPECT_NE(absent.find("\"heat\" float"), std::string::npos) << absent;
  const std::string vector = refusal_vdb_temperature_grid(path, grids, "velocity");
  EXPECT_NE(vector.find("vec3s"), std::string::npos) << vector;
  EXPECT_NE(vector.find("\"density\""), std::string::npos) << vector;
}

}  // namespace
}  // namespace pyro
