#pragma once
// How a medium scatters the sun's light towards the eye: a Henyey–Greenstein phase function with
// a forward lobe (the silver lining at the edges of a cloud seen against the sun), and an
// approximation of multiple scattering by octaves (Wrenninge, Kulla & Lundqvist 2013, "Oz: the
// great and volumetric", SIGGRAPH talk; used in Frostbite: Hillaire 2016, "Physically based sky, atmosphere
// and cloud rendering in Frostbite", SIGGRAPH course notes):
// the light scattered more than once is taken as further single-scattering terms, octave i with
// its optical depth scaled by a^i, its contribution by b^i and its phase eccentricity by c^i,
//   S_sun(μ, τ) = Σ_{i=0}^{n−1} b^i · 4π p_HG(μ, c^i g) · exp(−a^i τ).
// Octave 0 is single scattering: with n = 1 and g = 0 the sum is exp(−τ), the engine's lit media
// (components/volume_medium.h: a fully lit particle of albedo 1 shows the light's colour, the
// 4π folding the isotropic 1/(4π) into the light). Energy is not created when a ≥ b (Hillaire).
// μ = cos of the angle between the light's direction of travel and the direction towards the eye.

namespace pyro {

struct ScatteringOctaves {
  int octaves = 1;            // n ≥ 1; 1 = single scattering
  double attenuation = 0.25;  // a in (0, 1]: how much deeper light reaches in each octave
  double contribution = 0.5;  // b in [0, 1]: the weight of each octave over the one before
  double eccentricity = 0.5;  // c in [0, 1]: how much each octave's phase lobe flattens

  bool operator==(const ScatteringOctaves&) const = default;
};

struct SunScattering {
  double anisotropy = 0.0;  // g of the Henyey–Greenstein lobe, (−1, 1); 0 = isotropic
  ScatteringOctaves octaves;

  bool operator==(const SunScattering&) const = default;
};

// S_sun(μ, τ) above.
double sun_scattering(const SunScattering& s, double mu, double tau);

// Throws std::invalid_argument naming the field out of range.
void validate(const SunScattering& s);

}  // namespace pyro
