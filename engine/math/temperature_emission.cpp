#include "engine/math/temperature_emission.h"

#include <algorithm>

namespace pyro {

double TemperatureMapping::kelvin(double value) const {
  if (table.empty()) return scale * value + offset;
  if (value <= table.front().first) return table.front().second;
  if (value >= table.back().first) return table.back().second;
  const auto hi = std::upper_bound(table.begin(), table.end(), value,
                                   [](double v, const std::pair<double, double>& e) { return v < e.first; });
  const auto lo = hi - 1;
  const double f = (value - lo->first) / (hi->first - lo->first);
  return lo->second + f * (hi->second - lo->second);
}

TemperatureMapping automatic_temperature_mapping(double grid_max) {
  TemperatureMapping m;
  if (grid_max <= kNormalisedGridMax) {
    m.scale = (kFlameKelvin - kGlowKelvin) / std::max(grid_max, 1.0);
    m.offset = kGlowKelvin;
  }
  return m;
}

std::string automatic_mapping_kind(double grid_max) {
  return grid_max <= kNormalisedGridMax ? "normalised" : "kelvin";
}

TemperatureEmission make_temperature_emission(const TemperatureMapping& mapping, double intensity,
                                              double hottest_value) {
  TemperatureEmission e;
  e.mapping = mapping;
  e.intensity = intensity;
  e.hottest_kelvin = mapping.kelvin(hottest_value);
  if (e.hottest_kelvin > kGlowKelvin)
    e.table = blackbody_emission_table(kGlowKelvin, e.hottest_kelvin, float(intensity), 256);
  return e;
}

glm::vec3 emitted_radiance(const TemperatureEmission& emission, double value) {
  if (emission.table.size == 0) return glm::vec3(0.0f);
  const double kelvin = emission.mapping.kelvin(value);
  if (!(kelvin > kGlowKelvin)) return glm::vec3(0.0f);
  return sample_blackbody_rgb(emission.table, kelvin);
}

}  // namespace pyro
