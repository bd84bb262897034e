#pragma once
// Scripted camera motion: the camera circles its target about the vertical axis. The pose is a
// function of time (not accumulated), so any frame is reached directly.
#include <glm/vec3.hpp>

namespace pyro {

struct CameraOrbit {
  glm::vec3 start_position{0.0f};
  float deg_per_second = 0.0f;
};

}  // namespace pyro
