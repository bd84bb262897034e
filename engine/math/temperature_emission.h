#pragma once
// Fire from a temperature grid: a grid value becomes a temperature in kelvin (a per-volume map),
// and a temperature becomes emitted radiance from Planck's law and the CIE observer
// (engine/math/blackbody.h; Umenhoffer et al. 2006, section 3.2: fire is a black-body radiator).
//
// The emission model (Max 1995, "Optical models for direct volume rendering", section 2,
// absorption plus emission): along a ray dL/ds = -sigma_t L + sigma_t L_e, so the medium emits
// in proportion to its own extinction. A Gaussian particle of optical depth tau along a ray whose
// emitted radiance L_e is constant over it adds L_e (1 - exp(-tau)): the emission is weighted
// exactly like the particle's own opacity, in the splats and in the CPU references alike.
//
// L_e(T) = intensity * rgb(T) * Y(T) / Y(T_hot): the black body's linear sRGB chromaticity
// (largest component 1) times its luminance relative to the volume's hottest temperature T_hot,
// times `intensity`, which is therefore the largest component of the hottest emission. Below
// kGlowKelvin nothing is emitted (the table starts there).
#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "engine/math/blackbody.h"

namespace pyro {

// The lowest temperature that emits: 1000 K, a dull red whose luminance is 10^-5 of a 2500 K
// flame's (Planck), where a black body starts to glow visibly in the dark.
inline constexpr double kGlowKelvin = 1000.0;

// Grid value -> kelvin: either kelvin = scale * value + offset, or a table of (value, kelvin)
// pairs with values strictly ascending, linear between entries and held beyond the ends.
struct TemperatureMapping {
  double scale = 1.0, offset = 0.0;
  std::vector<std::pair<double, double>> table;  // non-empty: used instead of scale and offset
  double kelvin(double value) const;
};

// The mapping chosen for a grid whose largest value is `grid_max` when the scene or the command
// line names none. Grids whose values stay at or below kNormalisedGridMax hold a normalised
// heat (Blender's Mantaflow writes `heat`, `flame` and `temperature` roughly in [0, 1]): their
// range [0, max(grid_max, 1)] maps linearly onto the flame range [kGlowKelvin, kFlameKelvin].
// Larger values are taken to be kelvin already (scale 1, offset 0).
inline constexpr double kNormalisedGridMax = 10.0;
inline constexpr double kFlameKelvin = 2500.0;
TemperatureMapping automatic_temperature_mapping(double grid_max);
// "normalised" or "kelvin": what automatic_temperature_mapping decided, for reports.
std::string automatic_mapping_kind(double grid_max);

// The intensity a volume's fire has unless its scene says otherwise, and the one pyro import-vdb
// measures with: the hottest temperature glows at 4 times the display's white. A black body's
// luminance falls steeply below its hottest (Planck: a flame 25 % cooler in kelvin is tens of
// times dimmer), so at 1 only the hottest core would show; at 4 the flame's body does,
// and its core saturates towards yellow-white as a photographed flame does.
inline constexpr double kDefaultEmissionIntensity = 4.0;

// The emission of one volume: its mapping and the black-body table over [kGlowKelvin, T_hot].
struct TemperatureEmission {
  TemperatureMapping mapping;
  double intensity = 1.0;
  double hottest_kelvin = 0.0;  // T_hot; at or below kGlowKelvin nothing glows
  BlackbodyTable table;         // blackbody_emission_table(kGlowKelvin, T_hot, intensity)
};

// The emission of a volume whose hottest grid value is `hottest_value`.
TemperatureEmission make_temperature_emission(const TemperatureMapping& mapping, double intensity,
                                              double hottest_value);

// L_e of a grid value: 0 at or below kGlowKelvin, else the table at mapping.kelvin(value).
glm::vec3 emitted_radiance(const TemperatureEmission& emission, double value);

}  // namespace pyro
