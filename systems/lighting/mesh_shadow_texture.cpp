#include "systems/lighting/mesh_shadow_texture.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

void MeshShadowTexture::upload(const MeshShadow& shadow) {
  if (!texture_ || size_ != shadow.size) {
    texture_ = gpu::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.get(), 1, GL_DEPTH_COMPONENT32F, shadow.size.x, shadow.size.y);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.get(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(texture_.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    // Past the casters' grid nothing casts: the border is the far depth.
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T})
      glTextureParameteri(texture_.get(), wrap, GL_CLAMP_TO_BORDER);
    const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTextureParameterfv(texture_.get(), GL_TEXTURE_BORDER_COLOR, far);
    size_ = shadow.size;
  }
  glTextureSubImage2D(texture_.get(), 0, 0, 0, shadow.size.x, shadow.size.y, GL_DEPTH_COMPONENT, GL_FLOAT,
                      shadow.depth.data());
  version_ = shadow.version;
}

void MeshShadowTexture::bind(const gpu::Program& program, const MeshShadow* shadow, const glm::mat4& to_world) {
  const bool shadowed = shadow && !shadow->empty();
  glUniform1i(gpu::uniform_location(program, "u_mesh_shadowed"), shadowed ? 1 : 0);
  // Its own unit always: two samplers of different types on one unit fail every draw.
  glUniform1i(gpu::uniform_location(program, "u_mesh_shadow"), 2);
  if (!shadowed) return;
  if (shadow->version != version_) upload(*shadow);
  glBindTextureUnit(2, texture_.get());
  const glm::mat4 transform = shadow->world_to_texture * to_world;
  glUniformMatrix4fv(gpu::uniform_location(program, "u_mesh_shadow_transform"), 1, GL_FALSE,
                     glm::value_ptr(transform));
  glUniform1f(gpu::uniform_location(program, "u_mesh_shadow_texel_depth"), shadow->texel_depth);
  // The deepest shadow as an optical depth, as the particles' light caps it (absent from the
  // shaders that take the visibility alone).
  glUniform1f(gpu::uniform_location(program, "u_mesh_shadow_max_depth"), float(kMeshShadowDepth));
}

}  // namespace pyro
