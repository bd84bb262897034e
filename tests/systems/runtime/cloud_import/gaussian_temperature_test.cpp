// Each particle's temperature: the temperature grid's mean over the particle, weighted by the
// particle's profile times the grid's density (systems/runtime/cloud_import/gaussian_temperature.h),
// against closed forms: a uniform temperature is kept, a temperature linear in space gives its
// value at the centre of a particle whose weight is symmetric about it, a hot voxel with no
// density beside the particle does not heat it, and the result is the same on any thread count.
#include <gtest/gtest.h>

#include <algorithm>

#include "systems/runtime/cloud_import/gaussian_temperature.h"

namespace pyro {
namespace {

DenseGrid grid_of_gaussian_temperature(int n, float (*value)(int, int, int)) {
  DenseGrid g;
  g.dims = {n, n, n};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) g.values.push_back(value(x, y, z));
  return g;
}

GridGaussian at(float x, float y, float z, float sigma) {
  GridGaussian g;
  g.mean = {x, y, z};
  g.shape = glm::mat3(1.0f / sigma);
  g.peak = 1.0f;
  return g;
}

TEST(GaussianTemperature, UniformTemperatureIsKept) {
  const DenseGrid density = grid_of_gaussian_temperature(12, [](int, int, int) { return 0.5f; });
  const DenseGrid heat = grid_of_gaussian_temperature(12, [](int, int, int) { return 1700.0f; });
  const std::vector<float> t = gaussian_temperatures(density, heat, {at(5, 6, 5, 1.5f), at(2, 2, 9, 0.7f)});
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 1700.0f, 1e-2f);
  EXPECT_NEAR(t[1], 1700.0f, 1e-2f);
}

TEST(GaussianTemperature, LinearTemperatureGivesItsValueAtTheCentre) {
  const DenseGrid density = grid_of_gaussian_temperature(16, [](int, int, int) { return 1.0f; });
  const DenseGrid heat = grid_of_gaussian_temperature(16, [](int x, int y, int z) { return 1000.0f + 30.0f * x - 12.0f * y + 7.0f * z; });
  // Centres on voxel centres, ellipsoids inside the box: the weights are symmetric about them.
  const std::vector<GridGaussian> gs = {at(7, 8, 7, 1.2f), at(5, 9, 10, 0.8f)};
  const std::vector<float> t = gaussian_temperatures(density, heat, gs);
  for (size_t i = 0; i < gs.size(); ++i) {
    const glm::vec3 c = gs[i].mean;
    EXPECT_NEAR(t[i], 1000.0f + 30.0f * c.x - 12.0f * c.y + 7.0f * c.z, 1e-2f) << i;
  }
}

TEST(GaussianTemperature, HeatWhereThereIsNoDensityDoesNotCount) {
  // Density only at x <= 6; a very hot region at x >= 8 where there is no density.
  const DenseGrid density = grid_of_gaussian_temperature(14, [](int x, int, int) { return x <= 6 ? 1.0f : 0.0f; });
  const DenseGrid heat = grid_of_gaussian_temperature(14, [](int x, int, int) { return x >= 8 ? 5000.0f : 1200.0f; });
  const std::vector<float> t = gaussian_temperatures(density, heat, {at(6, 7, 7, 1.5f)});
  EXPECT_NEAR(t[0], 1200.0f, 1e-2f);
}

TEST(GaussianTemperature, SameOnAnyThreadCount) {
  const DenseGrid density = grid_of_gaussian_temperature(10, [](int x, int y, int z) { return float((x * 7 + y * 3 + z) % 5) * 0.2f; });
  const DenseGrid heat = grid_of_gaussian_temperature(10, [](int x, int y, int z) { return float(x * y + z); });
  std::vector<GridGaussian> gs;
  for (int i = 0; i < 20; ++i) gs.push_back(at(float(i % 10), float((i * 3) % 10), float((i * 7) % 10), 0.6f + 0.1f * (i % 4)));
  EXPECT_EQ(gaussian_temperatures(density, heat, gs, 1), gaussian_temperatures(density, heat, gs, 3));
}

TEST(GaussianTemperature, EmissionFollowsTheMap) {
  std::vector<AnisotropicGaussian> ps(2);
  const TemperatureEmission e = make_temperature_emission(automatic_temperature_mapping(1.0), 1.0, 1.0);
  apply_emission(ps, {1.0f, 0.0f}, e);
  EXPECT_EQ(ps[0].emission, emitted_radiance(e, 1.0));
  EXPECT_NEAR(std::max({ps[0].emission.x, ps[0].emission.y, ps[0].emission.z}), 1.0f, 1e-5f);
  EXPECT_EQ(ps[1].emission, glm::vec3(0.0f));  // 0 maps to the glow threshold: dark
}

}  // namespace
}  // namespace pyro
