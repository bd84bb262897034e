#pragma once
// One particle of a frame's media as the VDB export sees it: its extinction field (a clamped
// Gaussian, a sphere of the explosion's model or an anisotropic Gaussian: engine/math/shadow_caster.h,
// the same three shapes the light phase integrates), with the colour and temperature it carries.
#include <optional>

#include <glm/vec3.hpp>

#include "components/particle_medium.h"
#include "engine/math/shadow_caster.h"

namespace pyro {

struct MediaSample {
  ShadowCaster field;
  glm::vec3 color{1.0f};     // linear RGB, the particle's own (ParticlePool r, g, b)
  float temperature = 0.0f;  // kelvin (ParticlePool::temperature; 0 when it has none)
  glm::vec3 emission{0.0f};  // radiance emitted per unit of its extinction, linear RGB (Max 1995,
                             // absorption plus emission): a cloud's Gaussian's own; 0 for particle sets
  bool fire = false;         // a fire particle (ParticleMedium::fire)
  std::optional<ParticleMedium> medium;  // a particle set's particle: its medium; none for a cloud's
  double detail = 1.0;       // its finest length: a Gaussian's smallest standard deviation, r / 3
};

// The extinction (per world unit) of `s` at world point `p`: the clamped Gaussian's
// k exp(-|p - c|^2 / (2 s^2)) inside its cube, the ellipsoid's k exp(-m^2 / 2) for m <= 3, or the
// sphere's k g(|p - c| / r) (engine/math/sphere_field.h), whose projection is the billboards'.
double extinction_at(const MediaSample& s, const glm::dvec3& p);

// The half side of the axis-aligned box outside which `s` holds nothing.
double sample_reach(const MediaSample& s);

}  // namespace pyro
