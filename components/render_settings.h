#pragma once
// Resource: what the render systems need from the scene that is not an entity.
#include <glm/vec3.hpp>

namespace pyro {

struct RenderSettings {
  int width = 800;
  int height = 600;
  glm::vec3 background{0.62f, 0.68f, 0.76f};  // linear RGB
  glm::vec3 light_direction{-0.4f, -1.0f, -0.3f};
  glm::vec3 light_color{1.0f, 1.0f, 1.0f};
  glm::vec3 ambient{0.35f, 0.38f, 0.45f};
};

}  // namespace pyro
