#pragma once
// A box filled with identical Gaussian particles at uniformly random positions
// (Johnson & McAllister 2005, section 4). The emitter fills the entity's ParticleSet once.
#include <cstdint>

#include <glm/vec3.hpp>

namespace pyro {

struct CloudVolume {
  glm::vec3 box_min{-4.0f, 0.0f, -4.0f};
  glm::vec3 box_max{4.0f, 4.0f, 4.0f};
  uint32_t count = 1000;
  float radius = 0.4f;    // world units; the billboard's half side, kernel coordinate 3
  float density = 0.4f;   // rho: opacity at the kernel centre
  glm::vec3 color{0.8f, 0.8f, 0.8f};
  uint64_t seed = 1;      // already mixed with the scene seed
  glm::vec3 drift{0.0f, 0.0f, 0.0f};  // common velocity, world units per second
  float jitter = 0.0f;    // per-particle random speed added to the drift
  bool filled = false;    // set by the emitter once the particles exist
};

}  // namespace pyro
