#include "engine/mesh/mesh_placement.h"

#include <cmath>

#include <glm/trigonometric.hpp>

namespace pyro {

glm::mat3 MeshPlacement::rotation() const {
  const glm::vec3 a = glm::radians(rotation_deg);
  const float cx = std::cos(a.x), sx = std::sin(a.x), cy = std::cos(a.y), sy = std::sin(a.y),
              cz = std::cos(a.z), sz = std::sin(a.z);
  // glm is column-major: mat3(column 0, column 1, column 2).
  const glm::mat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::mat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::mat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return rz * ry * rx;
}

glm::mat4 MeshPlacement::model_matrix() const {
  glm::mat4 m(rotation() * scale);
  m[3] = glm::vec4(position, 1.0f);
  return m;
}

}  // namespace pyro
