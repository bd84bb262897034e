#pragma once
// Random initial states for emitted particles: scalar distributions, points in emitter shapes,
// directions in cones. Each function draws a fixed number of values from the stream, so the
// same seed gives the same particles whatever else runs.
#include <glm/vec3.hpp>

#include "components/distribution.h"
#include "components/emitter.h"
#include "engine/core/rng.h"

namespace pyro {

// constant: value; uniform: min + (max − min) u; normal: Box–Muller (two uniforms), clamped to
// [min, max]. Always draws two uniforms.
float sample_distribution(const Distribution& d, Rng& rng);

// A point in the emitter's shape (uniform in volume or area; on the surface for a surface
// sphere). Always draws three uniforms.
glm::vec3 sample_shape(const Emitter& e, Rng& rng);

// A unit direction uniform on the spherical cap of half-angle cone_deg about axis
// (cos θ uniform in [cos cone, 1]). Always draws two uniforms.
glm::vec3 sample_cone(const glm::vec3& axis, float cone_deg, Rng& rng);

// Two unit vectors completing `n` (unit) to a right-handed orthonormal basis (Duff et al. 2017).
void orthonormal_basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b);

}  // namespace pyro
