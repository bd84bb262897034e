#include "systems/lighting/opacity_map_texture.h"

#include <cmath>
#include <vector>

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

void OpacityMapTexture::upload(const ShadowVolume& map) {
  if (!texture_ || size_ != map.size) {
    texture_ = gpu::make_texture(GL_TEXTURE_3D);
    glTextureStorage3D(texture_.get(), 1, GL_R32F, map.size.x, map.size.y, map.size.z);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(texture_.get(), wrap, GL_CLAMP_TO_EDGE);
    size_ = map.size;
  }
  const float* texels = map.optical_depth.data();
  std::vector<float> transmittance;
  if (holds_ == OpacityMapHolds::transmittance) {
    transmittance.resize(map.optical_depth.size());
    for (std::size_t i = 0; i < transmittance.size(); ++i) transmittance[i] = std::exp(-map.optical_depth[i]);
    texels = transmittance.data();
  }
  glTextureSubImage3D(texture_.get(), 0, 0, 0, 0, map.size.x, map.size.y, map.size.z, GL_RED, GL_FLOAT, texels);
  version_ = map.version;
}

void OpacityMapTexture::bind(const gpu::Program& program, const ShadowVolume* map) {
  const bool shadowed = map && !map->empty();
  glUniform1i(gpu::uniform_location(program, "u_shadowed"), shadowed ? 1 : 0);
  // The sampler's unit is set even when nothing is bound: left at 0, it would share unit 0 with
  // a sampler of another type, and GL refuses to draw with such a program.
  glUniform1i(gpu::uniform_location(program, "u_shadow_map"), 1);
  if (!shadowed) return;
  if (map->version != version_) upload(*map);
  glBindTextureUnit(1, texture_.get());
  glUniformMatrix4fv(gpu::uniform_location(program, "u_world_to_shadow"), 1, GL_FALSE,
                     glm::value_ptr(map->world_to_texture));
}

}  // namespace pyro
