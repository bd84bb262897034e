#pragma once
// Black-body colour (Umenhoffer et al. 2006, section 3.2: fire particles are black-body
// radiators; their colour is Planck's spectrum integrated against the colour-matching
// functions). Everything here is computed from Planck's law and the CIE 1931 2° observer
// (engine/math/color_matching.h) at run time; GLSL receives make_blackbody_table()'s output as a
// texture, never hand-typed colours.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/math/color_matching.h"

namespace pyro {

// CODATA 2018 exact SI constants.
inline constexpr double planck_h = 6.62607015e-34;    // J s
inline constexpr double light_c = 299792458.0;        // m / s
inline constexpr double boltzmann_k = 1.380649e-23;   // J / K
// Second radiation constant c2 = h c / k = 1.438776877e-2 m K (the paper's C2 = 1.4388e-2).
inline constexpr double planck_c2 = planck_h * light_c / boltzmann_k;
// Maximum luminous efficacy of photopic vision, lm / W (CIE; Y = 683 ∫ L_λ ȳ dλ).
inline constexpr double luminous_efficacy_km = 683.0;

// Planck's law (Planck 1901), spectral radiance of a black body:
//   L_λ(λ, T) = 2 h c² / λ⁵ · 1 / (exp(h c / (λ k T)) − 1)     [W sr⁻¹ m⁻³]
// The paper (section 3.2) writes it as C1 / (λ⁵ (exp(C2 / (λ T)) − 1)) with C1 = 3.7418e-16 W m²
// = 2π h c², the spectral *exitance* (radiance times π); the factor cancels in every colour.
double planck_radiance(double wavelength_m, double temperature_k);

// CIE XYZ of a black body: X = ∫ L_λ x̄ dλ, Y = ∫ L_λ ȳ dλ, Z = ∫ L_λ z̄ dλ, λ in metres
// (trapezoid rule over the table's wavelengths), in W sr⁻¹ m⁻² weighted by the CMFs.
glm::dvec3 blackbody_xyz(double temperature_k, const ColorMatchingFunctions& cmf = cie1931_2deg());

// CIE XYZ of the equal-energy spectrum (S(λ) = 1): the CMFs' areas, in nm.
glm::dvec3 equal_energy_xyz(const ColorMatchingFunctions& cmf = cie1931_2deg());

// Chromaticity (x, y) = (X, Y) / (X + Y + Z) (CIE 1931).
glm::dvec2 xyz_chromaticity(const glm::dvec3& xyz);

// XYZ to linear sRGB, the matrix of IEC 61966-2-1:1999 (section 5.2), D65 white.
glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& xyz);

// The chromaticity of linear sRGB: xyz_chromaticity of the colour taken back to XYZ through the
// inverse of xyz_to_linear_srgb's matrix (so that a black body's colour gives its own xy).
glm::dvec2 linear_srgb_chromaticity(const glm::dvec3& rgb);

struct BlackbodyColor {
  double temperature_k = 0.0;
  glm::dvec3 xyz{0.0};      // normalised to Y = 1
  glm::dvec2 xy{0.0};       // chromaticity
  glm::dvec3 rgb{0.0};      // linear sRGB, negative components clamped to 0, max component 1
  bool in_gamut = true;     // false when a component was negative before clamping
  double luminance = 0.0;   // 683 ∫ L_λ ȳ dλ, cd / m²
};

BlackbodyColor blackbody_color(double temperature_k,
                               const ColorMatchingFunctions& cmf = cie1931_2deg());

// A table over temperature, evenly spaced from t_min to t_max inclusive, for the fire shader
// to sample as a 1D texture (node i at T = t_min + i (t_max − t_min) / (size − 1); with
// GL_LINEAR sampling put texel centres on the nodes: u = (i + 0.5) / size).
struct BlackbodyTable {
  double t_min = 1000.0;
  double t_max = 12000.0;
  int size = 0;
  std::vector<float> rgb;        // size × 3: linear sRGB, max component 1 (chromaticity only)
  std::vector<float> luminance;  // size: cd / m², for brightness that grows with temperature
};

BlackbodyTable make_blackbody_table(double t_min = 1000.0, double t_max = 12000.0, int size = 256,
                                    const ColorMatchingFunctions& cmf = cie1931_2deg());

// Fire's emitted radiance (Umenhoffer et al. 2006, section 3.2) on the table's nodes: each node's
// chromaticity times its luminance relative to the hottest node's, times `emission`, in `rgb`
// (what the explosion's fire shader reads, and what its derived lights emit).
BlackbodyTable blackbody_emission_table(double t_min, double t_max, float emission, int size);

// The table's rgb at T, linearly interpolated between nodes and clamped to the ends: what the
// shader's linear texture fetch returns.
glm::vec3 sample_blackbody_rgb(const BlackbodyTable& table, double temperature_k);

}  // namespace pyro
