#pragma once
// The consumer's own component: particles of an entity's ParticleSet turn about a vertical axis
// (through `center`) at `radians_per_second`, counter-clockwise seen from above (+y).
#include <glm/vec3.hpp>

namespace spin {

struct Spin {
  glm::vec3 center{0.0f};
  float radians_per_second = 0.0f;
};

}  // namespace spin
