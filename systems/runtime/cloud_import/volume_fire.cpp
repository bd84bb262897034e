#include "systems/runtime/cloud_import/volume_fire.h"

#include <cstdio>

namespace pyro {

TemperatureMapping volume_temperature_mapping(const VolumeEmissionDescription& d,
                                              const std::optional<TemperatureMapping>& recorded,
                                              double hottest_value) {
  if (d.automatic) return recorded ? *recorded : automatic_temperature_mapping(hottest_value);
  TemperatureMapping mapping;
  mapping.scale = d.scale;
  mapping.offset = d.offset;
  for (const std::array<float, 2>& e : d.table) mapping.table.emplace_back(e[0], e[1]);
  return mapping;
}

TemperatureEmission volume_temperature_emission(const VolumeEmissionDescription& d, const TemperatureMapping& mapping,
                                                double hottest_value, double exposure) {
  return make_temperature_emission(mapping, d.intensity_given ? double(d.intensity) : exposure, hottest_value);
}

std::string describe_volume_emission(const std::string& grid, const VolumeEmissionDescription& d, bool recorded,
                                     const TemperatureEmission& e) {
  char map[160];
  if (!e.mapping.table.empty())
    std::snprintf(map, sizeof map, "the scene's table of %zu entries", e.mapping.table.size());
  else
    std::snprintf(map, sizeof map, "kelvin = %g value + %g (%s)", e.mapping.scale, e.mapping.offset,
                  !d.automatic ? "the scene's" : recorded ? "as imported" : "automatic");
  char text[384];
  std::snprintf(text, sizeof text, "fire from temperature grid \"%s\": %s, hottest %.0f K%s, intensity %g (%s)",
                grid.c_str(), map, e.hottest_kelvin, e.hottest_kelvin > kGlowKelvin ? "" : " (too cool to glow)",
                e.intensity, d.intensity_given ? "the scene's" : recorded ? "as imported" : "exposed");
  return text;
}

bool add_emission_to_colours(std::vector<GaussianParticle>& particles, const std::vector<float>& temperatures,
                             const TemperatureEmission& emission) {
  bool any = false;
  for (size_t i = 0; i < particles.size() && i < temperatures.size(); ++i) {
    const glm::vec3 le = emitted_radiance(emission, temperatures[i]);
    particles[i].r += le.x;
    particles[i].g += le.y;
    particles[i].b += le.z;
    any = any || le.x > 0.0f || le.y > 0.0f || le.z > 0.0f;
  }
  return any;
}

}  // namespace pyro
