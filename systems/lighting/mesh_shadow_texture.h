#pragma once
// The meshes' shadow (components/mesh_shadow.h) as the opaque pass samples it: a depth texture
// compared and filtered by GL (sampler2DShadow, GL_LEQUAL, linear: the four nearest texels'
// tests weighed bilinearly, as mesh_visibility does on the CPU), uploaded when its version
// changes, with the uniforms u_mesh_shadowed, u_mesh_shadow (unit 2), u_mesh_shadow_transform
// (the shader's space to the grid's texture coordinates and depth) and u_mesh_shadow_texel_depth
// of mesh.frag and sphere_billboard.frag (LIT 2).
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "components/mesh_shadow.h"
#include "engine/gpu/gl_objects.h"

namespace pyro {

class MeshShadowTexture {
 public:
  // Sets `program`'s uniforms (in use) and binds the texture; null or empty: unshadowed.
  // `to_world` takes the shader's positions to world space (identity: they are world positions).
  void bind(const gpu::Program& program, const MeshShadow* shadow, const glm::mat4& to_world = glm::mat4(1.0f));

 private:
  void upload(const MeshShadow& shadow);
  gpu::Texture texture_;
  glm::ivec2 size_{0};
  uint64_t version_ = ~uint64_t(0);
};

}  // namespace pyro
