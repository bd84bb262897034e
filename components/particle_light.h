#pragma once
// The light reaching each particle of the entity's ParticleSet, written every frame by the light
// phase (systems/shadowing) in the pool's order, and read by the particle renderers: a particle's
// colour is its albedo (the pool's r, g, b) times `light`. Empty, or of another size than the
// pool (a world run without the light phase), means unlit: the pool's colours as they are.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace pyro {

struct ParticleLight {
  std::vector<float> sun_transmittance;  // exp(-optical depth) from the centre toward the sun
  std::vector<glm::vec3> light;          // sun colour x transmittance + ambient, linear RGB
  // The optical depth toward the sun of every other particle, at the centre (x) and its gradient
  // (yzw): with the particle's own, in closed form, the Gaussian splats shade each fragment
  // (content/shaders/billboard.frag, LIT).
  std::vector<glm::vec4> others_depth;

  bool covers(std::size_t particles) const { return light.size() == particles && particles > 0; }
};

}  // namespace pyro
