#include "engine/math/projected_sphere.h"

#include <cmath>

namespace pyro {

bool projected_sphere_rect(const glm::vec3& centre, float radius, const glm::mat4& projection,
                           glm::vec2 viewport, ScreenRect& out) {
  const float depth = -centre.z, r = radius;
  if (!(r > 0.0f) || !(depth > r)) return false;
  const float den = depth * depth - r * r;
  const glm::vec2 c(centre.x, centre.y);
  glm::vec2 root;
  for (int k = 0; k < 2; ++k) root[k] = std::sqrt(c[k] * c[k] + den);
  const glm::vec2 u_lo = (c * depth - r * root) / den, u_hi = (c * depth + r * root) / den;
  const glm::vec2 scale(projection[0][0], projection[1][1]);
  const glm::vec2 shift(projection[2][0], projection[2][1]);
  auto pixels = [&](glm::vec2 u) { return ((scale * u - shift) * 0.5f + 0.5f) * viewport; };
  out.lo = pixels(u_lo);
  out.hi = pixels(u_hi);
  return true;
}

}  // namespace pyro
