#pragma once
// A directional light that moves: keyframes over scene time, beside the DirectionalLight they
// set every frame (systems/lighting/light_animation.h). Times ascend; before the first key the
// light is the first key's, after the last the last's.
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct LightKeyframe {
  float time = 0.0f;  // seconds of scene time, >= 0
  glm::vec3 direction{-0.4f, -1.0f, -0.3f};  // the direction the light travels, not zero
  glm::vec3 color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
};

struct LightKeyframes {
  std::vector<LightKeyframe> keys;  // ascending times; empty: the light does not move
};

}  // namespace pyro
