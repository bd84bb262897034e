#pragma once
// Random anisotropic Gaussian particles for tests: uniformly random rotations (Shoemake's
// subgroup algorithm), scales, extinctions and colours from a seeded stream.
#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "engine/core/rng.h"
#include "engine/particles/anisotropic_gaussian.h"

namespace pyro::test {

// A uniformly distributed unit quaternion (K. Shoemake, "Uniform random rotations", Graphics
// Gems III, 1992).
inline glm::quat random_rotation(Rng& rng) {
  const float u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const float a = std::sqrt(1.0f - u1), b = std::sqrt(u1);
  const float t2 = 2.0f * std::numbers::pi_v<float> * u2, t3 = 2.0f * std::numbers::pi_v<float> * u3;
  return glm::quat(b * std::cos(t3), a * std::sin(t2), a * std::cos(t2), b * std::sin(t3));
}

// A particle with its centre in the box [-half, half]^3, scales in [s_lo, s_hi] on each axis
// independently, extinction in [k_lo, k_hi] and a cloud-like colour (brighter on top).
inline AnisotropicGaussian random_anisotropic(Rng& rng, float half, float s_lo, float s_hi,
                                              float k_lo, float k_hi) {
  AnisotropicGaussian g;
  g.centre = {rng.uniform(-half, half), rng.uniform(-half, half), rng.uniform(-half, half)};
  g.rotation = random_rotation(rng);
  g.scale = {rng.uniform(s_lo, s_hi), rng.uniform(s_lo, s_hi), rng.uniform(s_lo, s_hi)};
  g.extinction = rng.uniform(k_lo, k_hi);
  const float lit = 0.6f + 0.4f * (g.centre.y + half) / (2.0f * half);
  g.color = {lit, 0.97f * lit, 0.93f * lit};
  return g;
}

}  // namespace pyro::test
