#pragma once
// The light phase's opacity shadow map (components/shadow_volume.h) as the shaders sample it: a
// 3D texture, linear and clamped at the edges (as sample_optical_depth reads it on the CPU),
// uploaded when the map's version changes, with the uniforms u_shadowed, u_shadow_map (unit 1)
// and u_world_to_shadow of mesh.frag and billboard.frag.
//
// It holds the optical depth tau (mesh.frag), or the transmittance exp(-tau) (billboard.frag):
// across the edge of a dense medium tau rises by many units from one texel to the next, and
// interpolating tau there darkens the lit edge (the mean of exp(-tau) over a texel is near the
// texel nearer the light), where interpolating exp(-tau) keeps it lit.
#include <cstdint>

#include <glm/vec3.hpp>

#include "components/shadow_volume.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

enum class OpacityMapHolds { optical_depth, transmittance };

class OpacityMapTexture {
 public:
  explicit OpacityMapTexture(OpacityMapHolds holds = OpacityMapHolds::optical_depth) : holds_(holds) {}

  // Sets `program`'s uniforms (in use) and binds the texture; null or empty: unshadowed
  // (u_shadowed 0, the sampler still on unit 1).
  void bind(const gpu::Program& program, const ShadowVolume* map);

 private:
  void upload(const ShadowVolume& map);
  OpacityMapHolds holds_;
  gpu::Texture texture_;
  glm::ivec3 size_{0};
  uint64_t version_ = ~uint64_t(0);
};

}  // namespace pyro
