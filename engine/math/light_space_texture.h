#pragma once
// The world-to-texture matrix of a grid laid out in a light's frame (the opacity shadow map, the
// meshes' shadow): texture coordinate a of world point p is (dot(p, axis_a) - origin_a) / extent_a
// for the grid's axes u, v (across the light) and w (along it).
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace pyro {

inline glm::mat4 light_space_texture(const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w,
                                     const glm::dvec3& origin, const glm::dvec3& extent) {
  glm::mat4 m(0.0f);
  for (int a = 0; a < 3; ++a) {
    m[a][0] = float(u[a] / extent.x);
    m[a][1] = float(v[a] / extent.y);
    m[a][2] = float(w[a] / extent.z);
  }
  m[3] = glm::vec4(float(-origin.x / extent.x), float(-origin.y / extent.y), float(-origin.z / extent.z), 1.0f);
  return m;
}

}  // namespace pyro
