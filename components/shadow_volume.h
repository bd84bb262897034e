#pragma once
// Resource: the sun's optical depth through the particle media on a light-space grid, written
// once per frame by the light phase (systems/shadowing/opacity_shadow_map.h) and read by the
// opaque pass (systems/mesh_render) and by the shadow-map method for the particles themselves.
// Empty when no medium casts a shadow.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace pyro {

struct ShadowVolume {
  // Texel (i, j, k) holds the optical depth from the light's side of the media to the point
  // at texture coordinates ((i + 0.5) / size.x, (j + 0.5) / size.y, (k + 0.5) / size.z); world
  // points map to texture coordinates by `world_to_texture` (x across the light, z along it).
  glm::mat4 world_to_texture{1.0f};
  glm::ivec3 size{0};
  std::vector<float> optical_depth;  // x fastest, then y, then z
  uint64_t version = 0;              // changes whenever the contents do

  bool empty() const { return optical_depth.empty(); }
};

}  // namespace pyro
