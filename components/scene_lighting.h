#pragma once
// The scene's lights as the light phase publishes them once per frame (systems/lighting/
// lighting_system.h), whatever the number of eyes: every directional light and the ambient term.
// The render systems see them through one GPU block (components/light_block.h, content/shaders/
// lights.glsl) and the CPU's light-phase work (shadows, references) reads them here; none derives
// a light of its own.
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace pyro {

// A light at infinity as every consumer uses it.
struct SunLight {
  SunLight() = default;
  SunLight(const glm::vec3& travel_direction, const glm::vec3& light_radiance)
      : travel(travel_direction),
        toward(glm::length(travel_direction) > 0.0f ? -glm::normalize(travel_direction) : glm::vec3(0.0f)),
        radiance(light_radiance) {}

  glm::vec3 travel{-0.4f, -1.0f, -0.3f};  // the direction it travels, as the scene gives it
  glm::vec3 toward = -glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));  // unit, toward the light; 0 when travel is 0
  glm::vec3 radiance{1.0f, 1.0f, 1.0f};   // its colour times its intensity
};

struct SceneLighting {
  // Every directional light in entity-index order. A world run without the light phase is lit
  // by the default sun.
  std::vector<SunLight> suns{SunLight{}};
  glm::vec3 ambient{0.35f, 0.38f, 0.45f};  // the ambient lights' colours, summed

  // The key light: the first sun, which casts the shadows of the media and of the meshes; null
  // when the scene has no directional light.
  const SunLight* key() const { return suns.empty() ? nullptr : &suns.front(); }
  // The key light's radiance, black without one.
  glm::vec3 key_radiance() const { return suns.empty() ? glm::vec3(0.0f) : suns.front().radiance; }
  // Whether the key light shines from somewhere (a sun of zero direction lights nothing).
  bool key_shines() const { return !suns.empty() && glm::length(suns.front().travel) > 0.0f; }
};

}  // namespace pyro
