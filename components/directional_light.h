#pragma once
// A light at infinity (the sun, the moon): an entity's component. A scene may hold several
// (`lights` in docs/scene_format.md); the lighting phase (systems/lighting) gathers them into the
// SceneLighting resource that the render systems read.
#include <glm/vec3.hpp>

namespace pyro {

struct DirectionalLight {
  // The direction the light travels, as the scene gives it: not normalised here, since each
  // consumer normalises in the precision its maths needs.
  glm::vec3 direction{-0.4f, -1.0f, -0.3f};
  glm::vec3 color{1.0f, 1.0f, 1.0f};  // linear RGB, each >= 0
  float intensity = 1.0f;             // scales the colour, >= 0
};

}  // namespace pyro
