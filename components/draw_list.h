#pragma once
// Resource: every particle to draw this frame, back to front, as the GPU instance layout.
// Written by the sorting system, read by the billboard renderer and the CPU reference.
#include <vector>

#include <glm/vec4.hpp>

namespace pyro {

struct DrawList {
  std::vector<glm::vec4> center_radius;  // xyz world position, w radius
  std::vector<glm::vec4> color_density;  // rgb linear colour, a density rho
  // Explosion media (Umenhoffer et al. 2006): temperature (K), opacity (0-1), medium
  // (components/particle_medium.h, as a float), and a per-particle detail-window key in [0, 1).
  // Read only by the explosion shading; the Gaussian path does not upload it.
  std::vector<glm::vec4> medium;
  size_t size() const { return center_radius.size(); }
};

// Resource: one DrawList per rendered view (billboards facing the viewpoint are ordered by
// distance to each eye; facing the viewplane, every eye shares one order).
struct EyeDrawLists {
  std::vector<DrawList> eyes;
};

}  // namespace pyro
