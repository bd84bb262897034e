#pragma once
// Value noise: random values in [−1, 1) on the integer lattice (a hash of the lattice point and a
// seed), blended with quintic fades (Perlin 2002), so the field is C² smooth and its gradient
// exact. The potential of the curl-noise turbulence (systems/animation/curl_noise.h) and the
// pattern that gathers an emitter's births (systems/emitter).
#include <cstdint>

#include <glm/vec3.hpp>

namespace pyro {

// Value noise in [−1, 1] at p, and its exact gradient.
float value_noise(const glm::vec3& p, uint64_t seed, glm::vec3* gradient = nullptr);

}  // namespace pyro
