#pragma once
// GPU state of the composite phase: the reduced-resolution particle layer upsampled over the
// scene, and the views composed into the output image for the chosen stereo mode.
#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "engine/gpu/gl_objects.h"

#include <glm/mat3x3.hpp>

namespace pyro {

// How explosion media layers are composed (Umenhoffer et al. 2006, section 4).
struct MediaComposition {
  float near = 0.1f, far = 100.0f;  // the views' clip distances, for view depth
  float time = 0.0f;                // seconds, animates the shimmer's noise
  float shimmer = 0.0f;             // scene offset per unit fire opacity (fraction of the view)
  bool depth_aware = true;          // nearest-depth upsampling at depth edges; false: bilinear
  float depth_tolerance = 0.05f;    // relative view-depth spread still upsampled bilinearly
};

class Compositor {
 public:
  Compositor();
  void set_media(const MediaComposition& m) { media_ = m; }
  // Writes one view, its layer composited, into the linear float target `out` (same size):
  // the final composition's arithmetic without the sRGB encoding, for readback.
  void resolve_linear(const EyeTargets& view, const gpu::RenderTarget& out);
  // Writes frame.output from the views in frame.eyes (left, right) for `mode`, compositing each
  // view's particle layer over its scene on the way: one full-screen pass in all.
  // `swap_eyes`: the right view goes where the left one is expected, and the other way round.
  void compose(StereoMode mode, const GpuFrame& frame, bool swap_eyes = false);

 private:
  void bind_views(const EyeTargets& left, const EyeTargets& right);
  // Explosion media: the three layers composited, and their depths, at layer size.
  void prepare_media(const EyeTargets& eye);
  void draw_view(const glm::mat3& left_matrix, const glm::mat3& right_matrix, int x, int y,
                 int width, int height);
  gpu::Program compose_, media_compose_, media_prepare_;
  gpu::Framebuffer prepare_fbo_;  // two outputs: media_combined and media_depth
  const gpu::Program* current_ = nullptr;  // the program bind_views chose
  gpu::VertexArray empty_;
  MediaComposition media_;
  gpu::Texture noise_;  // made on first use
};

}  // namespace pyro
