#pragma once
// A scene volume's fire: its particles' temperatures (gaussian_temperature.h) made into emitted
// radiance with the entry's `emission` (docs/scene_format.md, volumes[].emission): the map from
// grid values to kelvin (the scene's, else the one the import recorded, else the automatic one,
// engine/math/temperature_emission.h) and the intensity of the hottest.
#include <optional>
#include <string>
#include <vector>

#include "engine/math/temperature_emission.h"
#include "engine/particles/anisotropic_gaussian.h"
#include "engine/particles/gaussian_particle.h"
#include "systems/runtime/scene/scene_description.h"

namespace pyro {

// The map from grid values to kelvin: the scene's, else `recorded` (the particle file's,
// engine/io/particle_file.h, recorded_temperature), else the automatic one for `hottest_value`.
TemperatureMapping volume_temperature_mapping(const VolumeEmissionDescription& description,
                                              const std::optional<TemperatureMapping>& recorded,
                                              double hottest_value);

// `hottest_value`: the largest temperature value of the grid the particles came from;
// `exposure`: the intensity when the scene gives none (the particle file's recorded exposure, or
// the grid's, fire_exposure.h).
TemperatureEmission volume_temperature_emission(const VolumeEmissionDescription& description,
                                                const TemperatureMapping& mapping, double hottest_value,
                                                double exposure);

// One line for the run's notes: the grid, how values become kelvin (and who decided), the
// hottest temperature and the intensity (and who decided: the scene, or the exposure).
std::string describe_volume_emission(const std::string& grid, const VolumeEmissionDescription& description,
                                     bool recorded, const TemperatureEmission& emission);

// Each isotropic particle's colour gains its emission (an unlit splat's premultiplied colour is
// (colour + L_e) rho f: emission weighted like the particle's own opacity). Returns whether any
// particle emits.
bool add_emission_to_colours(std::vector<GaussianParticle>& particles, const std::vector<float>& temperatures,
                             const TemperatureEmission& emission);

}  // namespace pyro
