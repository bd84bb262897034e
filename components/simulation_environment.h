#pragma once
// Resource: what every particle system of a scene shares: gravity, wind, the ambient
// temperature, and the simplified scene geometry particles collide with (Umenhoffer et al.
// 2006: particles collide with simplified scene geometry), plus the scene-wide particle budget.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace pyro {

struct SphereCollider {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
};

struct BoxCollider {  // axis-aligned
  glm::vec3 min{-1.0f}, max{1.0f};
};

struct SimulationEnvironment {
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  glm::vec3 wind{0.0f};
  float ambient_temperature = 293.0f;  // K
  bool ground = false;                 // a ground plane y = ground_height
  float ground_height = 0.0f;
  std::vector<SphereCollider> spheres;
  std::vector<BoxCollider> boxes;
  uint32_t particle_budget = 100000;   // live particles over all emitters
  uint64_t over_budget = 0;            // spawns refused by the scene budget
  uint64_t prewarm_steps = 0;          // steps run before frame 0 (emitters' time includes them)
};

}  // namespace pyro
