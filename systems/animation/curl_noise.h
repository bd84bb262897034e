#pragma once
// Curl-noise turbulence (Bridson, Houriham & Nordenstam 2007, "Curl-noise for procedural fluid
// flow"): the velocity u = ∇ × ψ of a smooth vector potential ψ is divergence-free
// (∇ · ∇ × ψ = 0), so particles swirl without bunching up or thinning out. ψ's components are
// three independent 3D value noises (engine/math/value_noise.h), differentiated analytically.
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/math/value_noise.h"

namespace pyro {

// ∇ × ψ at p, ψ = (noise(p; seed), noise(p; seed+1), noise(p; seed+2)).
glm::vec3 curl_noise(const glm::vec3& p, uint64_t seed);

}  // namespace pyro
