#pragma once
// Light from every direction (the sky's, the bounced light of the ground): an entity's
// component. The ambient lights of a scene add up (systems/lighting).
#include <glm/vec3.hpp>

namespace pyro {

struct AmbientLight {
  glm::vec3 color{0.35f, 0.38f, 0.45f};  // linear RGB, each >= 0
};

}  // namespace pyro
