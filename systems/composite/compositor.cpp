#include "systems/composite/compositor.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include "engine/gpu/gpu_pass_timer.h"
#include "engine/gpu/shader_program.h"
#include "engine/math/anaglyph.h"
#include "engine/math/camera_math.h"
#include "engine/math/color.h"
#include "engine/math/detail_noise.h"
#include "systems/composite/particle_depth_grid.h"

namespace pyro {


Compositor::Compositor()
    : media_prepare_(gpu::load_program("fullscreen.vert", "media_prepare.frag")),
      media_edges_(gpu::load_program("fullscreen.vert", "media_edges.frag")),
      cell_nearest_depth_(gpu::load_compute_program("cell_nearest_depth.comp")),
      prepare_fbo_(gpu::make_framebuffer()),
      empty_(gpu::make_vertex_array()) {}

const gpu::Program& Compositor::variant(bool use_left, bool use_right, const Features& f) {
  const bool media = media_bound_ && f.media;
  const bool full_size = media && f.full_size;
  const bool depth_aware = media && f.depth_aware && !full_size;
  const bool front = media && f.front && !depth_aware && !full_size;
  const bool shimmer = media && f.shimmer;
  const bool layers = layers_ && !media_bound_;
  const size_t key = size_t(use_left) | size_t(use_right) << 1 | size_t(layers) << 2 |
                     size_t(media) << 3 | size_t(depth_aware) << 4 | size_t(shimmer) << 5 |
                     size_t(f.tiled) << 6 | size_t(encode_) << 7 | size_t(full_size) << 8 |
                     size_t(front) << 9 | size_t(transparent_) << 10;
  gpu::Program& p = compose_[key];
  if (p.get() == 0) {
    auto flag = [](const char* name, bool on) { return std::string(name) + (on ? " 1" : " 0"); };
    std::vector<std::string> defines = {flag("USE_LEFT", use_left), flag("USE_RIGHT", use_right),
                                        flag("LAYERS", layers), flag("MEDIA", media),
                                        flag("DEPTH_AWARE", depth_aware), flag("FRONT", front),
                                        flag("FULL_SIZE", full_size), flag("SHIMMER", shimmer),
                                        flag("SRGB_ENCODE", encode_),
                                        flag("TRANSPARENT", transparent_)};
    if (encode_) defines.push_back(srgb_polynomial_define());
    p = gpu::load_program(f.tiled ? "compose_tile.vert" : "fullscreen.vert", "compose.frag", defines);
  }
  return p;
}

void Compositor::upload_shimmer_noise(float time) {
  if (shimmer_volume_.size == 0) {
    // The shimmer's noise field: the engine's periodic detail noise (its own seed).
    shimmer_volume_ = make_detail_noise(32, 4, 2, 0x5111eull);
    const int n = shimmer_volume_.size;
    shimmer_noise_ = gpu::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(shimmer_noise_.get(), 1, GL_RG16F, n, n);
    glTextureParameteri(shimmer_noise_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(shimmer_noise_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(shimmer_noise_.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(shimmer_noise_.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  }
  if (time == shimmer_noise_time_) return;
  shimmer_noise_time_ = time;
  const int n = shimmer_volume_.size;
  const std::vector<float> slice = detail_noise_slice_rg(shimmer_volume_, time);
  glTextureSubImage2D(shimmer_noise_.get(), 0, 0, 0, n, n, GL_RG, GL_FLOAT, slice.data());
}

void Compositor::bind_views(const EyeTargets& l, const EyeTargets& r) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(empty_.get());
  glBindTextureUnit(0, l.scene->color_texture());
  glBindTextureUnit(1, r.scene->color_texture());
  layers_ = l.layer != nullptr;
  media_bound_ = l.media_atlas != nullptr;
  if (layers_) {
    glBindTextureUnit(2, l.layer->color_texture());
    glBindTextureUnit(3, r.layer->color_texture());
  }
  if (!media_bound_) return;
  media_layer_size_ = {l.media_combined->width(), l.media_combined->height()};
  glBindTextureUnit(4, l.scene->depth_texture());
  glBindTextureUnit(5, r.scene->depth_texture());
  glBindTextureUnit(6, l.media_combined->color_texture());
  glBindTextureUnit(7, l.media_depth->color_texture());
  glBindTextureUnit(9, r.media_combined->color_texture());
  glBindTextureUnit(10, r.media_depth->color_texture());
  glBindTextureUnit(11, l.particle_depths.get());
  glBindTextureUnit(12, r.particle_depths.get());
  glBindTextureUnit(13, l.media_edges->color_texture());
  glBindTextureUnit(14, r.media_edges->color_texture());
  glBindTextureUnit(15, l.cell_nearest_depths.get());
  glBindTextureUnit(16, r.cell_nearest_depths.get());
}

void Compositor::prepare_media(EyeTargets& eye, bool edges) {
  const gpu::GpuPassScope pass("media prepare");  // profiling hook (no-op by default)
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
  const gpu::Program& program = media_prepare_;
  glUseProgram(program.get());
  glBindVertexArray(empty_.get());
  glBindTextureUnit(0, eye.media_atlas->color_texture());
  glBindTextureUnit(3, eye.scene->depth_texture());
  auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
  glUniform2f(loc("u_scale"), static_cast<float>(eye.scene->width()) / combined.width(),
              static_cast<float>(eye.scene->height()) / combined.height());
  glUniform1f(loc("u_near"), media_.near);
  glUniform1f(loc("u_far"), media_.far);
  glUniform1i(loc("u_cell_width"), combined.width());
  upload_shimmer_noise(media_.time);
  glBindTextureUnit(4, shimmer_noise_.get());
  glUniform1f(loc("u_shimmer"), media_.shimmer);
  glUniform1f(loc("u_shimmer_tiling"), 3.0f);  // noise periods across the view
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (edges) mark_edges(eye);
}

void Compositor::find_cell_nearest_depths(EyeTargets& eye) {
  const gpu::GpuPassScope pass("cell nearest depth");  // profiling hook (no-op by default)
  const glm::ivec2 cells = particle_depth_cells({eye.scene->width(), eye.scene->height()});
  glUseProgram(cell_nearest_depth_.get());
  glBindTextureUnit(0, eye.scene->depth_texture());
  glBindImageTexture(0, eye.cell_nearest_depths.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glUniform1i(gpu::uniform_location(cell_nearest_depth_, "u_cell"), ParticleDepthGrid::cell_pixels);
  glDispatchCompute(static_cast<GLuint>((cells.x + 7) / 8), static_cast<GLuint>((cells.y + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  eye.cell_nearest_version = eye.opaque_version;
}

void Compositor::mark_edges(EyeTargets& eye) {
  if (eye.cell_nearest_version != eye.opaque_version)
    find_cell_nearest_depths(eye);  // for compose_tiles.comp's front class
  const gpu::RenderTarget& edges = *eye.media_edges;
  glBindFramebuffer(GL_FRAMEBUFFER, edges.framebuffer());
  glViewport(0, 0, edges.width(), edges.height());
  glUseProgram(media_edges_.get());
  glBindTextureUnit(0, eye.media_depth->color_texture());
  glBindTextureUnit(1, eye.particle_depths.get());
  auto loc = [&](const char* name) { return gpu::uniform_location(media_edges_, name); };
  glUniform2f(loc("u_scale"), static_cast<float>(eye.scene->width()) / edges.width(),
              static_cast<float>(eye.scene->height()) / edges.height());
  glUniform1i(loc("u_depth_cell"), ParticleDepthGrid::cell_pixels);
  glUniform1f(loc("u_depth_tolerance"), media_.depth_tolerance);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Compositor::resolve_linear(const EyeTargets& view, const gpu::RenderTarget& out) {
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
  bind_views(view, view);
  draw_view(glm::mat3(1.0f), glm::mat3(0.0f), 0, 0, out.width(), out.height());
}

void Compositor::draw_view(const glm::mat3& left_matrix, const glm::mat3& right_matrix, int x,
                           int y, int width, int height, int slot, const SceneCopy& copy) {
  const glm::mat3 zero(0.0f);
  const bool use_left = left_matrix != zero, use_right = right_matrix != zero;
  glViewport(x, y, width, height);
  auto draw_with = [&](const gpu::Program& program) {
    glUseProgram(program.get());
    auto loc = [&](const char* name) { return gpu::uniform_location(program, name); };
    glUniformMatrix3fv(loc("u_left_matrix"), 1, GL_FALSE, glm::value_ptr(left_matrix));
    glUniformMatrix3fv(loc("u_right_matrix"), 1, GL_FALSE, glm::value_ptr(right_matrix));
    glUniform2i(loc("u_origin"), x, y);
    glUniform2f(loc("u_view_size"), static_cast<float>(width), static_cast<float>(height));
    if (media_bound_) {
      glUniform1f(loc("u_depth_tolerance"), media_.depth_tolerance);
      glUniform1i(loc("u_depth_cell"), ParticleDepthGrid::cell_pixels);
      const glm::vec2 terms = inverse_depth_terms(media_.near, media_.far);
      glUniform2f(loc("u_inverse_depth"), terms.x, terms.y);
    }
  };
  // Layers at full size need no upsampling: every pixel reads its own texel.
  const bool reduced = media_bound_ && media_layer_size_ != glm::ivec2(width, height);
  Features all;
  all.full_size = !reduced;
  all.depth_aware = media_.depth_aware && reduced;
  all.shimmer = media_.shimmer > 0.0f;
  if (!media_bound_ || !media_.tiles) {
    draw_with(variant(use_left, use_right, all));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  const ComposeTiles::Grid grid = ComposeTiles::grid_for({width, height}, media_layer_size_);
  ComposeTiles::Classify how;
  how.use_left = use_left;
  how.use_right = use_right;
  how.edges = all.depth_aware;
  how.inverse_depth = inverse_depth_terms(media_.near, media_.far);
  how.fire = all.shimmer;
  {
    const gpu::GpuPassScope pass("tile classify");
    tiles_.classify(grid, how, slot);
  }
  for (unsigned cls : ComposeTiles::classes) {
    if (cls == 0 && copy.from != 0) {
      // Tiles without media show the scene unchanged: a copy of its sRGB bytes, the same
      // bytes the scene-only variant writes, for a fraction of its cost on llvmpipe.
      const gpu::GpuPassScope pass("scene copy");
      glCopyImageSubData(copy.from, GL_TEXTURE_2D, 0, 0, 0, 0, copy.to, GL_TEXTURE_2D, 0, x, y, 0,
                         width, height, 1);
      continue;
    }
    Features f;
    f.tiled = true;
    f.full_size = all.full_size;
    f.media = (cls & ComposeTiles::media) != 0;
    f.depth_aware = (cls & ComposeTiles::edge) != 0;
    f.front = (cls & ComposeTiles::front) != 0;
    f.shimmer = (cls & ComposeTiles::fire) != 0;
    if (((f.depth_aware || f.front) && !all.depth_aware) || (f.shimmer && !all.shimmer))
      continue;  // never filled
    static constexpr const char* names[16] = {
        "scene tiles", "media tiles", "", "depth-edge tiles", "", "fire tiles", "",
        "fire and depth-edge tiles", "", "front tiles", "", "", "", "fire and front tiles", "", ""};
    const gpu::GpuPassScope pass(names[cls]);
    const gpu::Program& program = variant(use_left, use_right, f);
    draw_with(program);
    tiles_.draw(program.get(), grid, cls, slot, {x, y});
  }
  glUseProgram(0);
}

void Compositor::compose(StereoMode mode, GpuFrame& frame, bool swap_eyes, float motion_blur) {
  for (EyeTargets& eye : frame.eyes)
    if (eye.media_combined) {
      const bool reduced = eye.media_combined->width() != eye.scene->width() ||
                           eye.media_combined->height() != eye.scene->height();
      prepare_media(eye, media_.depth_aware && reduced);
    }
  const gpu::RenderTarget& out = *frame.output;
  const bool blur = motion_blur > 0.0f && frame.history;
  if (blur) {
    // Blend into the linear history: src (1 - b) + dst b.
    glBindFramebuffer(GL_FRAMEBUFFER, frame.history->framebuffer());
    glDisable(GL_FRAMEBUFFER_SRGB);
  } else {
    glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer());
    glEnable(GL_FRAMEBUFFER_SRGB);  // linear in, sRGB-encoded bytes out (on for every pass)
  }
  // The output's bytes written by the shaders (the history, when blurring, stays linear).
  encode_ = !blur && out.format() == GL_SRGB8_ALPHA8;
  if (encode_) glDisable(GL_FRAMEBUFFER_SRGB);
  const size_t first = swap_eyes && frame.eyes.size() > 1 ? 1 : 0;
  const EyeTargets& l = frame.eyes[first];
  const EyeTargets& r = frame.eyes.size() > 1 ? frame.eyes[1 - first] : frame.eyes[0];
  bind_views(l, r);
  if (blur && frame.history_valid) {
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, motion_blur);
    glBlendFunc(GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA);
  }
  const int w = l.scene->width(), h = l.scene->height();
  const glm::mat3 I(1.0f), Z(0.0f);
  // A view drawn alone and unblended, from an sRGB scene into the sRGB output: its tiles without
  // media may be copied (the scene target is 8-bit sRGB whenever media are composited).
  auto copy_of = [&](const EyeTargets& eye) {
    SceneCopy c;
    if (!blur && media_bound_ && eye.scene->format() == out.format()) {
      c.from = eye.scene->color_texture();
      c.to = out.color_texture();
    }
    return c;
  };
  switch (mode) {
    case StereoMode::mono:
      draw_view(I, Z, 0, 0, w, h, 0, copy_of(l));
      break;
    case StereoMode::left_right:
    case StereoMode::side_by_side:
      draw_view(I, Z, 0, 0, w, h, 0, copy_of(l));
      draw_view(Z, I, w, 0, w, h, 1, copy_of(r));
      break;
    case StereoMode::side_by_side_crossed:
      draw_view(Z, I, 0, 0, w, h, 0, copy_of(r));
      draw_view(I, Z, w, 0, w, h, 1, copy_of(l));
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
  if (encode_) glEnable(GL_FRAMEBUFFER_SRGB);
  encode_ = false;
  if (blur) {
    glDisable(GL_BLEND);
    frame.history_valid = true;
    // The history, encoded to sRGB on the way into the output (GL_FRAMEBUFFER_SRGB on).
    glEnable(GL_FRAMEBUFFER_SRGB);
    glBlitNamedFramebuffer(frame.history->framebuffer(), out.framebuffer(), 0, 0, out.width(),
                           out.height(), 0, 0, out.width(), out.height(), GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
  }
}

}  // namespace pyro
