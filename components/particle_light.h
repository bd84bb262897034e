#pragma once
// What the light phase (systems/shadowing) works out for each particle of the entity's
// ParticleSet (in the pool's order) or AnisotropicCloud (in its order), every frame: the optical
// depth toward the sun of every other particle at its centre (x) and its gradient (yzw). With the
// particle's own, in closed form, the lit splats shade each fragment (content/shaders/
// billboard.frag and anisotropic_splat.frag, LIT); the particles' colours are then albedos. Of another size than the pool (a world run without the light phase):
// no shadow from the others.
#include <vector>

#include <glm/vec4.hpp>

namespace pyro {

struct ParticleLight {
  std::vector<glm::vec4> others_depth;
};

}  // namespace pyro
