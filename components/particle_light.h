#pragma once
// What the light phase (systems/shadowing) works out for each particle of the entity's
// ParticleSet, in the pool's order, every frame: the optical depth toward the sun of every other
// particle at its centre (x) and its gradient (yzw). With the particle's own, in closed form, the
// lit Gaussian splats shade each fragment (content/shaders/billboard.frag, LIT); the pool's
// colours are then albedos. Of another size than the pool (a world run without the light phase):
// no shadow from the others.
#include <vector>

#include <glm/vec4.hpp>

namespace pyro {

struct ParticleLight {
  std::vector<glm::vec4> others_depth;
};

}  // namespace pyro
