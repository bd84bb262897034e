#include "systems/animation/curl_noise.h"

namespace pyro {

glm::vec3 curl_noise(const glm::vec3& p, uint64_t seed) {
  glm::vec3 g1, g2, g3;
  // Offsets decorrelate the three components' lattices as well as their seeds.
  value_noise(p, seed, &g1);
  value_noise(p + glm::vec3(31.416f, -47.853f, 12.793f), seed + 1, &g2);
  value_noise(p + glm::vec3(-19.191f, 23.719f, -61.137f), seed + 2, &g3);
  // ∇ × ψ = (∂ψ3/∂y − ∂ψ2/∂z, ∂ψ1/∂z − ∂ψ3/∂x, ∂ψ2/∂x − ∂ψ1/∂y)
  return {g3.y - g2.z, g1.z - g3.x, g2.x - g1.y};
}

}  // namespace pyro
