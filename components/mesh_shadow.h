#pragma once
// Resource: the meshes' shadow from the key light, written once a frame by the light phase
// (systems/shadowing/mesh_shadow_map.h) and read by the opaque pass (systems/mesh_render), which
// shadows the meshes and the ground, and by the particles' light (systems/shadowing), which
// shadows the media. On a light-space grid across the light: per texel the depth along the light
// of the nearest caster surface through the texel's centre. Empty when no mesh casts a shadow.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace pyro {

// The deepest mesh shadow as an optical depth, -ln of e^-16 of the light (none worth drawing):
// the particles' light (systems/shadowing/mesh_shadow_map.h, mesh_shadow_depth) and the
// explosion's per-fragment truth (sphere_billboard.frag, as a uniform) cap the meshes' shadow at it.
inline constexpr double kMeshShadowDepth = 16.0;

struct MeshShadow {
  // World points to the grid's texture coordinates: x and y across the light in [0, 1] over the
  // grid, z along the light (0 at the nearest caster's depth range start, 1 at the farthest
  // mesh's end).
  glm::mat4 world_to_texture{1.0f};
  glm::ivec2 size{0};
  std::vector<float> depth;   // x fastest: the nearest caster's texture z through the texel, 1 if none
  float texel_depth = 0.0f;   // a texel's side in texture-z units: the receivers' depth bias scale
  uint64_t version = 0;       // changes whenever the contents do

  bool empty() const { return depth.empty(); }
};

}  // namespace pyro
