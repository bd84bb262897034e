#include "systems/emitter/emitter_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace pyro {

float sample_distribution(const Distribution& d, Rng& rng) {
  const float u1 = rng.uniform(), u2 = rng.uniform();
  switch (d.kind) {
    case DistributionKind::constant:
      return d.value;
    case DistributionKind::uniform:
      return d.min + (d.max - d.min) * u1;
    case DistributionKind::normal: {
      // Box–Muller; 1 − u1 is in (0, 1], so the log is finite.
      const float z = std::sqrt(-2.0f * std::log(1.0f - u1)) *
                      std::cos(2.0f * std::numbers::pi_v<float> * u2);
      return std::clamp(d.mean + d.stddev * z, d.min, d.max);
    }
  }
  return d.value;
}

void orthonormal_basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

glm::vec3 sample_cone(const glm::vec3& axis, float cone_deg, Rng& rng) {
  const float u1 = rng.uniform(), u2 = rng.uniform();
  const float cos_max = std::cos(std::clamp(cone_deg, 0.0f, 180.0f) * std::numbers::pi_v<float> / 180.0f);
  const float c = 1.0f - u1 * (1.0f - cos_max);
  const float s = std::sqrt(std::max(0.0f, 1.0f - c * c));
  const float phi = 2.0f * std::numbers::pi_v<float> * u2;
  const glm::vec3 n = glm::normalize(axis);
  glm::vec3 t, b;
  orthonormal_basis(n, t, b);
  return c * n + s * std::cos(phi) * t + s * std::sin(phi) * b;
}

glm::vec3 sample_shape(const Emitter& e, Rng& rng) {
  const float u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  switch (e.shape) {
    case EmitterShape::point:
      return e.position;
    case EmitterShape::sphere: {
      // Direction uniform on the sphere (z uniform in [−1, 1]); radius ∝ cbrt(u) fills the volume.
      const float z = 1.0f - 2.0f * u1;
      const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const float phi = 2.0f * std::numbers::pi_v<float> * u2;
      const float r = e.surface ? e.radius : e.radius * std::cbrt(u3);
      return e.position + r * glm::vec3(s * std::cos(phi), s * std::sin(phi), z);
    }
    case EmitterShape::box:
      return e.position + e.half_extent * glm::vec3(2.0f * u1 - 1.0f, 2.0f * u2 - 1.0f, 2.0f * u3 - 1.0f);
    case EmitterShape::disc: {
      glm::vec3 t, b;
      orthonormal_basis(glm::normalize(e.axis), t, b);
      const float r = e.radius * std::sqrt(u1);  // uniform in area
      const float phi = 2.0f * std::numbers::pi_v<float> * u2;
      return e.position + r * (std::cos(phi) * t + std::sin(phi) * b);
    }
  }
  return e.position;
}

}  // namespace pyro
