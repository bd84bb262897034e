#include "systems/billboard_render/billboard_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include "engine/gpu/shader_program.h"

namespace pyro {

BillboardRenderer::BillboardRenderer(const FootprintTable& table)
    : table_(table),
      kernel_program_(gpu::load_program("billboard.vert", "billboard.frag")),
      trivial_program_(gpu::load_program("billboard.vert", "billboard_trivial.frag")) {
  // The kernel texture: one texel per footprint-table node (eq. 2 maps pixels to nodes),
  // sampled bilinearly between nodes and clamped at the billboard's edge.
  kernel_texture_ = gpu::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(kernel_texture_.get(), 1, GL_R32F, table_.size, table_.size);
  glTextureSubImage2D(kernel_texture_.get(), 0, 0, 0, table_.size, table_.size, GL_RED, GL_FLOAT,
                      table_.scaled.data());
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(kernel_texture_.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void BillboardRenderer::draw(const DrawList& list, const CameraFrame& frame,
                             const gpu::RenderTarget& target, BillboardAlignment alignment,
                             BillboardShading shading) {
  const size_t n = list.size();
  if (n == 0) return;
  const GLuint vao = instances_.upload(list);

  target.bind();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over", back to front
  glDisable(GL_CULL_FACE);
  const gpu::Program& program =
      shading == BillboardShading::kernel ? kernel_program_ : trivial_program_;
  glUseProgram(program.get());
  glUniformMatrix4fv(gpu::uniform_location(program, "u_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(frame.view_projection));
  glUniform3fv(gpu::uniform_location(program, "u_right"), 1, glm::value_ptr(frame.right));
  glUniform3fv(gpu::uniform_location(program, "u_up"), 1, glm::value_ptr(frame.up));
  glUniform3fv(gpu::uniform_location(program, "u_eye"), 1, glm::value_ptr(frame.eye));
  glUniform1i(gpu::uniform_location(program, "u_face_viewpoint"),
              alignment == BillboardAlignment::viewpoint ? 1 : 0);
  const float t0 = static_cast<float>(footprint_texcoord(table_, -table_.extent));
  const float t1 = static_cast<float>(footprint_texcoord(table_, table_.extent));
  glUniform2f(gpu::uniform_location(program, "u_texcoord_bias_scale"), t0, t1 - t0);
  glBindTextureUnit(0, kernel_texture_.get());
  glBindVertexArray(vao);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(n));
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

}  // namespace pyro
