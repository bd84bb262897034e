// The fire's exposure (systems/runtime/cloud_import/fire_exposure.h) against closed forms: a
// uniform hot box emits 1 - e^-tau along every line through it; a column of flame is exposed for
// its sides, not its length (the median of the six directions); a hot core is dimmed by the
// smoke in front of it from each side, by the smoke's transmittance; the exposed intensity brings
// the median to the exposure, and a fire that does not glow keeps the default intensity.
#include <gtest/gtest.h>

#include <cmath>

#include "systems/runtime/cloud_import/fire_exposure.h"

namespace pyro {
namespace {

// An n x n x n box of voxel size `voxel`, each voxel's value from f(x, y, z).
template <class F>
DenseGrid exposure_box(int n, double voxel, F f) {
  DenseGrid g;
  g.dims = {n, n, n};
  g.index_to_world = glm::dmat4(voxel);
  g.index_to_world[3][3] = 1.0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        g.values.push_back(float(f(x, y, z)));
        g.max_value = std::max(g.max_value, g.values.back());
      }
  return g;
}

// Kelvin as stored: the hottest voxel at 2000 K, whose colour's largest channel is 1 at
// intensity 1 (engine/math/temperature_emission.h).
const TemperatureMapping kKelvin{};

TEST(FireExposure, AUniformHotBoxEmitsOneMinusItsTransmittance) {
  const double voxel = 0.25, extinction = 0.8, rho = 1.5;
  const int n = 10;
  const DenseGrid density = exposure_box(n, voxel, [&](int, int, int) { return rho; });
  const DenseGrid heat = exposure_box(n, voxel, [](int, int, int) { return 2000.0; });
  const TemperatureEmission unit = make_temperature_emission(kKelvin, 1.0, heat.max_value);
  const double tau = extinction * rho * n * voxel;
  EXPECT_NEAR(brightest_fire_sightline(density, extinction, heat, unit), 1.0 - std::exp(-tau), 1e-6);
  EXPECT_NEAR(exposed_fire_intensity(density, extinction, heat, kKelvin), kFireExposure / (1.0 - std::exp(-tau)), 1e-5);
}

TEST(FireExposure, AColumnOfFlameIsExposedForItsSidesNotItsLength) {
  // Fire only in a 4 x 4 column along y: along y each line crosses 10 voxels of it, along x and
  // z 4. The six directions' brightest lines sort F4, F4, F4, F4, F10, F10: the median is F4.
  const double voxel = 0.1, extinction = 2.0, rho = 0.5;
  const int n = 10;
  const auto in_column = [](int x, int z) { return x >= 3 && x <= 6 && z >= 3 && z <= 6; };
  const DenseGrid density = exposure_box(n, voxel, [&](int x, int, int z) { return in_column(x, z) ? rho : 0.0; });
  const DenseGrid heat = exposure_box(n, voxel, [&](int x, int, int z) { return in_column(x, z) ? 2000.0 : 0.0; });
  const TemperatureEmission unit = make_temperature_emission(kKelvin, 1.0, heat.max_value);
  const double side = 1.0 - std::exp(-extinction * rho * 4 * voxel), length = 1.0 - std::exp(-extinction * rho * n * voxel);
  EXPECT_NEAR(brightest_fire_sightline(density, extinction, heat, unit), side, 1e-6);
  EXPECT_GT(length, 1.5 * side);
}

TEST(FireExposure, SmokeInFrontDimsTheFireFromItsSideOnly) {
  // A hot core (x >= 4, 2 <= y, z <= 7; density 0.5) wrapped in cold smoke (density 3): on the
  // x >= 4 side nothing covers it, 4 voxels of smoke on the other, 2 on either side along y and
  // z. The six directions' brightest lines sort S4 F, S2 F (four times), F: the median is S2 F,
  // the core seen through two voxels of smoke (S_k = e^-(extinction 3 k voxel), F = 1 - e^-tau
  // of the core's 6 voxels).
  const double voxel = 0.1, extinction = 2.0;
  const int n = 10;
  const auto core = [](int x, int y, int z) { return x >= 4 && y >= 2 && y <= 7 && z >= 2 && z <= 7; };
  const DenseGrid density = exposure_box(n, voxel, [&](int x, int y, int z) { return core(x, y, z) ? 0.5 : 3.0; });
  const DenseGrid heat = exposure_box(n, voxel, [&](int x, int y, int z) { return core(x, y, z) ? 2000.0 : 500.0; });
  const TemperatureEmission unit = make_temperature_emission(kKelvin, 1.0, heat.max_value);
  const double fire = 1.0 - std::exp(-extinction * 0.5 * 6 * voxel), smoke_two = std::exp(-extinction * 3.0 * 2 * voxel);
  EXPECT_NEAR(brightest_fire_sightline(density, extinction, heat, unit), smoke_two * fire, 1e-6);
  EXPECT_NEAR(exposed_fire_intensity(density, extinction, heat, kKelvin), kFireExposure / (smoke_two * fire), 1e-5);
}

TEST(FireExposure, AFireThatDoesNotGlowKeepsTheDefaultIntensity) {
  const DenseGrid density = exposure_box(6, 1.0, [](int, int, int) { return 1.0; });
  const DenseGrid cold = exposure_box(6, 1.0, [](int, int, int) { return 900.0; });
  EXPECT_EQ(exposed_fire_intensity(density, 1.0, cold, kKelvin), kDefaultEmissionIntensity);
  // A wisp too thin to reach the exposure is held at the cap.
  const DenseGrid wisp = exposure_box(6, 1.0, [](int, int, int) { return 1e-6; });
  const DenseGrid hot = exposure_box(6, 1.0, [](int, int, int) { return 2000.0; });
  EXPECT_EQ(exposed_fire_intensity(wisp, 1.0, hot, kKelvin), kMaxExposedIntensity);
}

}  // namespace
}  // namespace pyro
