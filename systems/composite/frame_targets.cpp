#include "systems/composite/frame_targets.h"

#include <algorithm>
#include <cmath>

#include "systems/composite/particle_depth_grid.h"

namespace pyro {

int layer_extent(int full, float scale) {
  return std::max(1, static_cast<int>(std::lround(full * static_cast<double>(scale))));
}

GpuFrame make_gpu_frame(const RenderSettings& settings) {
  GpuFrame f;
  RenderSettings s = settings;  // the views' size
  s.width = layer_extent(settings.width, settings.frame_scale);
  s.height = layer_extent(settings.height, settings.frame_scale);
  const size_t views = is_stereo(s.stereo_mode) ? 2 : 1;
  for (size_t v = 0; v < views; ++v) {
    EyeTargets t;
    // Particles blend into the scene target only at full resolution; then it must be float.
    // With a layer, it holds opaque geometry alone: 8-bit sRGB keeps dark tones precise and
    // is about twice as fast to clear, shade and read on llvmpipe as RGBA16F.
    const bool media = s.media_layers();
    const GLenum scene_format = s.layer_scale < 1.0f || media ? GL_SRGB8_ALPHA8 : GL_RGBA16F;
    t.scene = std::make_unique<gpu::RenderTarget>(s.width, s.height, scene_format);
    if (media) {
      const int lw = layer_extent(s.width, s.layer_scale), lh = layer_extent(s.height, s.layer_scale);
      t.media_atlas = std::make_unique<gpu::RenderTarget>(3 * lw, lh);
      t.media_combined = std::make_unique<gpu::RenderTarget>(lw, lh);
      t.media_depth = std::make_unique<gpu::RenderTarget>(lw, lh, GL_RGBA16F);
      t.media_edges = std::make_unique<gpu::RenderTarget>(lw, lh, GL_R8);
      const glm::ivec2 cells = particle_depth_cells({s.width, s.height});
      t.particle_depths = gpu::make_texture(GL_TEXTURE_2D);
      glTextureStorage2D(t.particle_depths.get(), 1, GL_RG32F, cells.x, cells.y);
      glTextureParameteri(t.particle_depths.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(t.particle_depths.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      t.cell_nearest_depths = gpu::make_texture(GL_TEXTURE_2D);
      glTextureStorage2D(t.cell_nearest_depths.get(), 1, GL_R32F, cells.x, cells.y);
      glTextureParameteri(t.cell_nearest_depths.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(t.cell_nearest_depths.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    } else if (s.layer_scale < 1.0f)
      t.layer = std::make_unique<gpu::RenderTarget>(layer_extent(s.width, s.layer_scale),
                                                    layer_extent(s.height, s.layer_scale));
    f.eyes.push_back(std::move(t));
  }
  const int out_width = output_width(s.width, s.stereo_mode);
  f.output = std::make_unique<gpu::RenderTarget>(out_width, s.height, GL_SRGB8_ALPHA8);
  if (settings.motion_blur > 0.0f)
    f.history = std::make_unique<gpu::RenderTarget>(f.output->width(), f.output->height(), GL_RGBA16F);
  if (settings.frame_scale < 1.0f) {
    const int display_width = output_width(settings.width, s.stereo_mode);
    f.display = std::make_unique<gpu::RenderTarget>(display_width, settings.height, GL_SRGB8_ALPHA8);
  }
  return f;
}

}  // namespace pyro
