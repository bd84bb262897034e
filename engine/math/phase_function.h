#pragma once
// Phase functions for single scattering in dust and smoke (Umenhoffer et al. 2006, section 3.1).
// Convention: p is a probability density over the sphere of outgoing directions,
// ∫ p dΩ = 1, so an isotropic medium has p = 1 / (4π). μ = cos θ = ω'·ω, the cosine between the
// photon's direction before and after scattering (μ = 1: straight on, forward scattering).
//
// The formula the paper prints and calls Henyey–Greenstein is the Cornette–Shanks function
// (Cornette & Shanks 1992, eq. 8): it carries the Rayleigh-like factor (1 + μ²) and the
// normalisation 3 (1 − g²) / (2 (2 + g²)). See docs/explosions.md.
#include <string>
#include <string_view>
#include <vector>

namespace pyro {

enum class PhaseFunction { henyey_greenstein, cornette_shanks };

// Henyey & Greenstein 1941: p(μ) = (1 − g²) / (4π (1 + g² − 2 g μ)^{3/2}). Mean cosine = g.
double henyey_greenstein(double mu, double g);

// The cosine μ of a direction drawn from Henyey–Greenstein for a uniform ξ in [0, 1): the
// inverse of its cumulative distribution in μ, 2π ∫_{-1}^{μ} p = ξ, which solves to
//   μ = (1 + g² − ((1 − g²) / (1 − g + 2 g ξ))²) / (2 g), and μ = 1 − 2ξ when g = 0.
// ξ = 0 gives μ = −1 and ξ → 1 gives μ = 1.
double sample_henyey_greenstein_cosine(double g, double xi);

// Cornette & Shanks 1992, eq. 8 (the paper's section 3.1 formula):
//   p(μ) = 1/(4π) · 3 (1 − g²) (1 + μ²) / (2 (2 + g²) (1 + g² − 2 g μ)^{3/2}).
// g is its parameter, not its mean cosine; that is cornette_shanks_mean_cosine(g).
double cornette_shanks(double mu, double g);

// ⟨μ⟩ = 2π ∫ μ p(μ) dμ for Cornette–Shanks, in closed form: 3 g (4 + g²) / (5 (2 + g²))
// (Cornette & Shanks 1992, eq. 9). It equals g at g = 0 and ±1 only.
double cornette_shanks_mean_cosine(double g);

double phase(PhaseFunction f, double mu, double g);
const char* phase_function_name(PhaseFunction f);  // "henyey-greenstein", "cornette-shanks"
bool parse_phase_function(std::string_view name, PhaseFunction& out);

struct SphereIntegral {
  double integral = 0.0;     // ∫ p dΩ
  double mean_cosine = 0.0;  // ∫ μ p dΩ
};

// Numerical quadrature over the whole sphere of directions ω for a fixed, oblique incoming
// direction ω' (so p is evaluated through real 3D dot products, not through its symmetry):
// composite Simpson in the polar cosine with `cos_intervals` (even) intervals about the z axis,
// times the midpoint rule with `azimuth_steps` steps in the azimuth.
SphereIntegral integrate_over_sphere(PhaseFunction f, double g, int cos_intervals = 4096,
                                     int azimuth_steps = 96);

}  // namespace pyro
