#pragma once
// A perspective camera looking from `position` at `target`.
#include <glm/vec3.hpp>

namespace pyro {

struct Camera {
  glm::vec3 position{0.0f, 1.5f, 8.0f};
  glm::vec3 target{0.0f, 1.5f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;
  float near = 0.1f;
  float far = 200.0f;
  float orbit_deg_per_second = 0.0f;  // scripted orbit about the target's vertical axis
};

}  // namespace pyro
