#pragma once
// What the render systems know of the scene's lights, written once per frame by the lighting
// phase (systems/lighting/lighting_system.h) from the light entities, whatever the number of
// eyes. The shading methods so far use one directional light (the first) and the ambient term.
#include <glm/vec3.hpp>

namespace pyro {

struct SceneLighting {
  // The first directional light (lowest entity index): its travel direction as given (not
  // normalised) and its colour times its intensity; black when the scene has none.
  glm::vec3 sun_direction{-0.4f, -1.0f, -0.3f};
  glm::vec3 sun_color{1.0f, 1.0f, 1.0f};
  glm::vec3 ambient{0.35f, 0.38f, 0.45f};  // the ambient lights' colours, summed
  int directional_lights = 1;              // how many the scene holds (only the first is shaded)
};

}  // namespace pyro
