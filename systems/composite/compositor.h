#pragma once
// GPU state of the composite phase: the reduced-resolution particle layer upsampled over the
// scene, and the views composed into the output image for the chosen stereo mode.
#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "engine/gpu/gl_objects.h"

#include <glm/mat3x3.hpp>

namespace pyro {

class Compositor {
 public:
  Compositor();
  // Blends `layer` (premultiplied) over `scene`, upsampled bilinearly (for readback; the final
  // composition does the same on the fly).
  void upsample_layer(const gpu::RenderTarget& layer, const gpu::RenderTarget& scene);
  // Writes frame.output from the views in frame.eyes (left, right) for `mode`, compositing each
  // view's particle layer over its scene on the way: one full-screen pass in all.
  void compose(StereoMode mode, const GpuFrame& frame);

 private:
  void draw_view(const glm::mat3& left_matrix, const glm::mat3& right_matrix, int x, int y,
                 int width, int height);
  gpu::Program upsample_, compose_;
  gpu::VertexArray empty_;
};

}  // namespace pyro
