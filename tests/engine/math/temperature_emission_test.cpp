// Fire from temperature values: the map from grid values to kelvin, the automatic choice between
// normalised and kelvin grids, and the emitted radiance against Planck's law through
// blackbody_color (engine/math/blackbody.h), computed here independently of the table.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/math/blackbody.h"
#include "engine/math/temperature_emission.h"

namespace pyro {
namespace {

TEST(TemperatureMapping, ScaleAndOffsetAreLinear) {
  const TemperatureMapping m{1500.0, 1000.0, {}};
  EXPECT_DOUBLE_EQ(m.kelvin(0.0), 1000.0);
  EXPECT_DOUBLE_EQ(m.kelvin(0.5), 1750.0);
  EXPECT_DOUBLE_EQ(m.kelvin(1.0), 2500.0);
}

TEST(TemperatureMapping, TableInterpolatesAndHoldsItsEnds) {
  TemperatureMapping m;
  m.table = {{0.0, 800.0}, {1.0, 1800.0}, {3.0, 2200.0}};
  EXPECT_DOUBLE_EQ(m.kelvin(-5.0), 800.0);
  EXPECT_DOUBLE_EQ(m.kelvin(0.25), 1050.0);
  EXPECT_DOUBLE_EQ(m.kelvin(2.0), 2000.0);
  EXPECT_DOUBLE_EQ(m.kelvin(7.0), 2200.0);
}

TEST(TemperatureMapping, NormalisedGridsMapOntoTheFlameRange) {
  const TemperatureMapping unit = automatic_temperature_mapping(0.8);  // below 1: [0, 1] still the range
  EXPECT_DOUBLE_EQ(unit.kelvin(0.0), kGlowKelvin);
  EXPECT_DOUBLE_EQ(unit.kelvin(1.0), kFlameKelvin);
  const TemperatureMapping wide = automatic_temperature_mapping(4.0);  // Mantaflow heat past 1
  EXPECT_DOUBLE_EQ(wide.kelvin(4.0), kFlameKelvin);
  EXPECT_DOUBLE_EQ(wide.kelvin(2.0), 0.5 * (kGlowKelvin + kFlameKelvin));
  EXPECT_EQ(automatic_mapping_kind(4.0), "normalised");
}

TEST(TemperatureMapping, LargeValuesAreKelvinAlready) {
  const TemperatureMapping k = automatic_temperature_mapping(1850.0);
  EXPECT_DOUBLE_EQ(k.kelvin(1850.0), 1850.0);
  EXPECT_DOUBLE_EQ(k.kelvin(300.0), 300.0);
  EXPECT_EQ(automatic_mapping_kind(1850.0), "kelvin");
}

TEST(TemperatureEmission, HottestGlowsAtTheIntensityWithItsBlackBodyColour) {
  TemperatureMapping kelvin;  // identity
  const TemperatureEmission e = make_temperature_emission(kelvin, 2.5, 2400.0);
  const BlackbodyColor hot = blackbody_color(2400.0);
  const glm::vec3 le = emitted_radiance(e, 2400.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(le[c], 2.5 * hot.rgb[c], 1e-4) << c;
  EXPECT_NEAR(std::max({le.x, le.y, le.z}), 2.5f, 1e-4f);
}

TEST(TemperatureEmission, CoolerGlowsDimmerAndRedderByPlancksLaw) {
  const TemperatureEmission e = make_temperature_emission(TemperatureMapping{}, 1.0, 2500.0);
  // A table node (256 nodes over [1000, 2500]: node 128 at 1000 + 128 * 1500 / 255).
  const double t = 1000.0 + 128.0 * 1500.0 / 255.0;
  const BlackbodyColor cool = blackbody_color(t), hot = blackbody_color(2500.0);
  const glm::vec3 le = emitted_radiance(e, t);
  const double relative = cool.luminance / hot.luminance;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(le[c], relative * cool.rgb[c], 1e-6 + 1e-4 * relative) << c;
  const glm::vec3 top = emitted_radiance(e, 2500.0);
  EXPECT_GT(le.x / le.y, top.x / top.y);  // redder
}

TEST(TemperatureEmission, NothingGlowsAtOrBelowTheGlowTemperature) {
  const TemperatureEmission e = make_temperature_emission(TemperatureMapping{}, 1.0, 2000.0);
  EXPECT_EQ(emitted_radiance(e, kGlowKelvin), glm::vec3(0.0f));
  EXPECT_EQ(emitted_radiance(e, 300.0), glm::vec3(0.0f));
  const TemperatureEmission cold = make_temperature_emission(TemperatureMapping{}, 1.0, 900.0);
  EXPECT_EQ(emitted_radiance(cold, 900.0), glm::vec3(0.0f));
}

}  // namespace
}  // namespace pyro
