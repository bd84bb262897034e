#pragma once
// Resource: how explosion particles are shaded (Umenhoffer et al. 2006, sections 3 and 4).
// Per medium (components/particle_medium.h: dust, smoke, fire) an albedo a and phase-function
// parameter g for eq. 1, the amplitude of the detail-noise perturbation, and for fire the
// black-body temperature range, scale and bias. Defaults are the paper's.
#include <array>

namespace pyro {

struct MediumShading {
  float albedo = 0.0f;            // a in eq. 1: dust 0.9, smoke 0.2 (section 3.1); fire 0
  float g = 0.0f;                 // Cornette-Shanks parameter; the paper uses 0
  float detail_amplitude = 0.5f;  // opacity *= 1 + amplitude (2 n - 1), n the detail noise

  friend bool operator==(const MediumShading&, const MediumShading&) = default;
};

struct ExplosionShading {
  std::array<MediumShading, 3> media{{
      {0.9f, 0.0f, 0.5f},  // dust
      {0.2f, 0.0f, 0.5f},  // smoke
      {0.0f, 0.0f, 0.0f},  // fire: no scattering; its detail perturbs temperature
  }};
  // In-scattered radiance of a directional light is E P(mu), P in 1/sr; E = light colour times
  // this irradiance scale (4 pi: an isotropic medium would scatter exactly the light colour).
  float light_irradiance = 12.566371f;
  // Fire (section 3.2): T = bias + scale (T_particle + detail_range (n - 1/2)), looked up in the
  // black-body table over [t_min, t_max] (the paper's 2500-3200 K); brightness follows the
  // black body's luminance relative to t_max, times `emission`.
  float fire_t_min = 2500.0f;
  float fire_t_max = 3200.0f;
  float fire_scale = 1.0f;
  float fire_bias = 0.0f;
  float fire_detail_range = 500.0f;
  float fire_emission = 6.0f;
  // The detail window: noise texels per particle radius, and how fast (periods per second) a
  // particle's window moves through the volume's time axis.
  float detail_frequency = 0.35f;
  float detail_speed = 0.25f;
  // Heat shimmer (section 4): the scene lookup moves by this fraction of the view per unit of
  // fire opacity, along a noise field.
  float shimmer = 0.006f;

  friend bool operator==(const ExplosionShading&, const ExplosionShading&) = default;
};

}  // namespace pyro
