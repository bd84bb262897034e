#include "systems/composite/compositor.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "engine/gpu/shader_program.h"
#include "engine/math/anaglyph.h"

namespace pyro {

Compositor::Compositor()
    : upsample_(gpu::load_program("fullscreen.vert", "layer_upsample.frag")),
      compose_(gpu::load_program("fullscreen.vert", "stereo_compose.frag")),
      empty_(gpu::make_vertex_array()) {}

void Compositor::upsample_layer(const gpu::RenderTarget& layer, const gpu::RenderTarget& scene) {
  scene.bind();
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glUseProgram(upsample_.get());
  glBindTextureUnit(0, layer.color_texture());
  glBindVertexArray(empty_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

void Compositor::draw_view(GLuint left, GLuint right, const float* left_matrix,
                           const float* right_matrix, int x, int y, int width, int height) {
  glViewport(x, y, width, height);
  glBindTextureUnit(0, left);
  glBindTextureUnit(1, right);
  glUniformMatrix3fv(gpu::uniform_location(compose_, "u_left_matrix"), 1, GL_FALSE, left_matrix);
  glUniformMatrix3fv(gpu::uniform_location(compose_, "u_right_matrix"), 1, GL_FALSE, right_matrix);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Compositor::compose(StereoMode mode, const GpuFrame& frame) {
  const gpu::RenderTarget& out = *frame.output;
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
  glEnable(GL_FRAMEBUFFER_SRGB);  // linear in, sRGB-encoded bytes out
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(compose_.get());
  glBindVertexArray(empty_.get());
  const glm::mat3 identity(1.0f), zero(0.0f);
  const GLuint left = frame.eyes[0].scene->color_texture();
  const GLuint right = frame.eyes.size() > 1 ? frame.eyes[1].scene->color_texture() : left;
  const int w = frame.eyes[0].scene->width(), h = frame.eyes[0].scene->height();
  const float* I = glm::value_ptr(identity);
  const float* Z = glm::value_ptr(zero);
  switch (mode) {
    case StereoMode::mono:
      draw_view(left, left, I, Z, 0, 0, w, h);
      break;
    case StereoMode::left_right:
    case StereoMode::side_by_side:
      draw_view(left, right, I, Z, 0, 0, w, h);
      draw_view(left, right, Z, I, w, 0, w, h);
      break;
    case StereoMode::side_by_side_crossed:
      draw_view(left, right, Z, I, 0, 0, w, h);
      draw_view(left, right, I, Z, w, 0, w, h);
      break;
    case StereoMode::anaglyph:
    case StereoMode::anaglyph_color:
    case StereoMode::anaglyph_half_color: {
      const AnaglyphKind kind = mode == StereoMode::anaglyph         ? AnaglyphKind::dubois
                                : mode == StereoMode::anaglyph_color ? AnaglyphKind::color
                                                                     : AnaglyphKind::half_color;
      const AnaglyphMatrices m = anaglyph_matrices(kind);
      draw_view(left, right, glm::value_ptr(m.left), glm::value_ptr(m.right), 0, 0, w, h);
      break;
    }
  }
  glDisable(GL_FRAMEBUFFER_SRGB);
}

}  // namespace pyro
