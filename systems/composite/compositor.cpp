#include "systems/composite/compositor.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "engine/gpu/shader_program.h"
#include "engine/math/anaglyph.h"
#include "engine/math/detail_noise.h"

namespace pyro {

Compositor::Compositor()
    : compose_(gpu::load_program("fullscreen.vert", "stereo_compose.frag")),
      media_compose_(gpu::load_program("fullscreen.vert", "media_compose.frag")),
      media_prepare_(gpu::load_program("fullscreen.vert", "media_prepare.frag")),
      prepare_fbo_(gpu::make_framebuffer()),
      empty_(gpu::make_vertex_array()) {}

void Compositor::bind_views(const EyeTargets& l, const EyeTargets& r) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const bool media = l.media[0] != nullptr;
  current_ = media ? &media_compose_ : &compose_;
  glUseProgram(current_->get());
  glBindVertexArray(empty_.get());
  glBindTextureUnit(0, l.scene->color_texture());
  glBindTextureUnit(1, r.scene->color_texture());
  const bool layers = l.layer != nullptr;
  glUniform1i(gpu::uniform_location(*current_, "u_has_layers"), layers ? 1 : 0);
  if (layers) {
    glBindTextureUnit(2, l.layer->color_texture());
    glBindTextureUnit(3, r.layer->color_texture());
  }
  if (!media) return;
  glUniform1i(gpu::uniform_location(*current_, "u_has_media"), 1);
  if (noise_.get() == 0) {
    // The shimmer's noise field: the engine's periodic detail noise (its own seed).
    const DetailNoise n = make_detail_noise(32, 4, 2, 0x5111eull);
    noise_ = gpu::make_texture(GL_TEXTURE_3D);
    glTextureStorage3D(noise_.get(), 1, GL_R16F, n.size, n.size, n.size);
    glTextureSubImage3D(noise_.get(), 0, 0, 0, 0, n.size, n.size, n.size, GL_RED, GL_FLOAT, n.values.data());
    glTextureParameteri(noise_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(noise_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum w : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
      glTextureParameteri(noise_.get(), w, GL_REPEAT);
  }
  glBindTextureUnit(4, l.scene->depth_texture());
  glBindTextureUnit(5, r.scene->depth_texture());
  glBindTextureUnit(6, l.media_combined->color_texture());
  glBindTextureUnit(7, l.media_depth->color_texture());
  glBindTextureUnit(9, r.media_combined->color_texture());
  glBindTextureUnit(10, r.media_depth->color_texture());
  glBindTextureUnit(12, noise_.get());
  auto loc = [&](const char* name) { return gpu::uniform_location(*current_, name); };
  glUniform1i(loc("u_upsample"), media_.depth_aware ? 1 : 0);
  glUniform1f(loc("u_depth_tolerance"), media_.depth_tolerance);
  glUniform1f(loc("u_near"), media_.near);
  glUniform1f(loc("u_far"), media_.far);
  glUniform1f(loc("u_shimmer"), media_.shimmer);
  glUniform1f(loc("u_time"), media_.time);
}

void Compositor::prepare_media(const EyeTargets& eye) {
  const gpu::RenderTarget& combined = *eye.media_combined;
  const GLuint fbo = prepare_fbo_.get();
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, combined.color_texture(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, eye.media_depth->color_texture(), 0);
  const GLenum outputs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo, 2, outputs);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, combined.width(), combined.height());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(media_prepare_.get());
  glBindVertexArray(empty_.get());
  for (int m = 0; m < 3; ++m) glBindTextureUnit(static_cast<GLuint>(m), eye.media[m]->color_texture());
  glBindTextureUnit(3, eye.scene->depth_texture());
  auto loc = [&](const char* name) { return gpu::uniform_location(media_prepare_, name); };
  glUniform2f(loc("u_scale"), static_cast<float>(eye.scene->width()) / combined.width(),
              static_cast<float>(eye.scene->height()) / combined.height());
  glUniform1f(loc("u_near"), media_.near);
  glUniform1f(loc("u_far"), media_.far);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Compositor::resolve_linear(const EyeTargets& view, const gpu::RenderTarget& out) {
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
  bind_views(view, view);
  draw_view(glm::mat3(1.0f), glm::mat3(0.0f), 0, 0, out.width(), out.height());
}

void Compositor::draw_view(const glm::mat3& left_matrix, const glm::mat3& right_matrix, int x,
                           int y, int width, int height) {
  const glm::mat3 zero(0.0f);
  glViewport(x, y, width, height);
  glUniformMatrix3fv(gpu::uniform_location(*current_, "u_left_matrix"), 1, GL_FALSE, glm::value_ptr(left_matrix));
  glUniformMatrix3fv(gpu::uniform_location(*current_, "u_right_matrix"), 1, GL_FALSE, glm::value_ptr(right_matrix));
  glUniform1i(gpu::uniform_location(*current_, "u_use_left"), left_matrix != zero ? 1 : 0);
  glUniform1i(gpu::uniform_location(*current_, "u_use_right"), right_matrix != zero ? 1 : 0);
  glUniform2i(gpu::uniform_location(*current_, "u_origin"), x, y);
  glUniform2f(gpu::uniform_location(*current_, "u_view_size"), static_cast<float>(width),
              static_cast<float>(height));
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Compositor::compose(StereoMode mode, const GpuFrame& frame, bool swap_eyes) {
  for (const EyeTargets& eye : frame.eyes)
    if (eye.media_combined) prepare_media(eye);
  const gpu::RenderTarget& out = *frame.output;
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
  glEnable(GL_FRAMEBUFFER_SRGB);  // linear in, sRGB-encoded bytes out (on for every pass)
  const size_t first = swap_eyes && frame.eyes.size() > 1 ? 1 : 0;
  const EyeTargets& l = frame.eyes[first];
  const EyeTargets& r = frame.eyes.size() > 1 ? frame.eyes[1 - first] : frame.eyes[0];
  bind_views(l, r);
  const int w = l.scene->width(), h = l.scene->height();
  const glm::mat3 I(1.0f), Z(0.0f);
  switch (mode) {
    case StereoMode::mono:
      draw_view(I, Z, 0, 0, w, h);
      break;
    case StereoMode::left_right:
    case StereoMode::side_by_side:
      draw_view(I, Z, 0, 0, w, h);
      draw_view(Z, I, w, 0, w, h);
      break;
    case StereoMode::side_by_side_crossed:
      draw_view(Z, I, 0, 0, w, h);
      draw_view(I, Z, w, 0, w, h);
      break;
    case StereoMode::anaglyph:
    case StereoMode::anaglyph_color:
    case StereoMode::anaglyph_half_color: {
      const AnaglyphKind kind = mode == StereoMode::anaglyph         ? AnaglyphKind::dubois
                                : mode == StereoMode::anaglyph_color ? AnaglyphKind::color
                                                                     : AnaglyphKind::half_color;
      const AnaglyphMatrices m = anaglyph_matrices(kind);
      draw_view(m.left, m.right, 0, 0, w, h);
      break;
    }
  }
}

}  // namespace pyro
