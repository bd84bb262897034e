#pragma once
// The scene the render tests measure against closed forms: one white particle at `at` (its
// emitter's box `spread` either side of it) over a black background, seen from the origin along
// -z. Callers change what their test needs (stereo, lighting, shading).
#include <glm/vec3.hpp>

#include "systems/runtime/scene/scene_description.h"

namespace pyro::test {

inline SceneDescription one_particle_scene(const glm::vec3& at, float radius, float density,
                                           int width, int height, float fov_y_deg,
                                           float spread = 0.0f) {
  SceneDescription s;
  s.width = width;
  s.height = height;
  s.background = {0.0f, 0.0f, 0.0f};
  s.camera.position = {0.0f, 0.0f, 0.0f};
  s.camera.target = {0.0f, 0.0f, -1.0f};
  s.camera.fov_y_deg = fov_y_deg;
  CloudDescription c;
  c.count = 1;
  c.radius = radius;
  c.density = density;
  c.color = {1.0f, 1.0f, 1.0f};
  c.box_min = at - glm::vec3(spread);
  c.box_max = at + glm::vec3(spread);
  s.clouds.push_back(c);
  return s;
}

}  // namespace pyro::test
