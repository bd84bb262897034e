#pragma once
// One anisotropic Gaussian particle: a sample of a medium whose extinction is
//   sigma(p) = extinction * exp(-m(p)^2 / 2),  m(p)^2 = (p - centre)^T Sigma^-1 (p - centre),
//   Sigma = R S^2 R^T,  R = rotation (local axes to world), S = diag(scale),
// truncated to the ellipsoid m <= kAnisotropicExtent (3 standard deviations along every
// principal axis; outside it the particle holds nothing). The isotropic Gaussian particle
// (gaussian_particle.h) is the case scale = (s, s, s), apart from its truncation to a cube.
// Colour is linear RGB with the lighting already applied, as for the isotropic particles.
// Emission is the radiance L_e the particle's medium emits (a fire's black-body light,
// engine/math/temperature_emission.h): along a ray of optical depth tau through the particle it
// adds L_e (1 - exp(-tau)), weighted exactly like the particle's own opacity; 0 for smoke.
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace pyro {

// The truncation radius in standard deviations (Mahalanobis distance).
inline constexpr float kAnisotropicExtent = 3.0f;

struct AnisotropicGaussian {
  glm::vec3 centre{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z: local axes to world
  glm::vec3 scale{1.0f};                       // standard deviations along the local axes
  float extinction = 0.0f;                     // peak extinction (per world unit) at the centre
  glm::vec3 color{1.0f};
  glm::vec3 emission{0.0f};                    // emitted radiance, linear RGB (not lit)
};

// Sigma^-1 = R S^-2 R^T.
inline glm::mat3 inverse_covariance(const AnisotropicGaussian& g) {
  const glm::mat3 r = glm::mat3_cast(glm::normalize(g.rotation));
  const glm::vec3 inv = 1.0f / (g.scale * g.scale);
  const glm::mat3 d(inv.x, 0, 0, 0, inv.y, 0, 0, 0, inv.z);
  return r * d * glm::transpose(r);
}

// sigma(p) as defined above, truncation included.
inline float extinction_at(const AnisotropicGaussian& g, const glm::mat3& inv_cov, const glm::vec3& p) {
  const glm::vec3 d = p - g.centre;
  const float m2 = glm::dot(d, inv_cov * d);
  return m2 <= kAnisotropicExtent * kAnisotropicExtent ? g.extinction * std::exp(-0.5f * m2) : 0.0f;
}

}  // namespace pyro
