#pragma once
// Resource: the frame's offscreen targets, shared by the render and composite passes.
// Per rendered view: the scene target (opaque geometry with depth, then the particles: linear
// RGBA16F) and, when particles render at reduced resolution, their layer (RGBA16F; the scene
// target is then 8-bit sRGB, since only opaque geometry is drawn into it). One output target
// holds the composed sRGB image (two views side by side for side-by-side and left-right).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "engine/gpu/render_target.h"

namespace pyro {

struct EyeTargets {
  std::unique_ptr<gpu::RenderTarget> scene;
  std::unique_ptr<gpu::RenderTarget> layer;  // null when the layer scale is 1 or with media
  // Explosion shading (RenderSettings::media_layers()): the dust, smoke and fire layers (RGBA16F,
  // premultiplied) at the layer scale, any scale including 1, as three cells side by side in one
  // target (cell m from column m * media_combined's width): one framebuffer for the three
  // layers, so that llvmpipe rasterises them in one pass, its threads sharing the cells, where
  // three small targets would each go to one thread in turn. Null otherwise.
  std::unique_ptr<gpu::RenderTarget> media_atlas;
  // Made from the three each frame at layer size before the final pass: the media composited
  // in order (premultiplied RGBA16F), and (RGBA16F) 1/z of the view depth z each layer texel was
  // rendered against, the fire's opacity and the heat shimmer's offset, so the full-size pass
  // reads one layer, not three.
  std::unique_ptr<gpu::RenderTarget> media_combined;
  std::unique_ptr<gpu::RenderTarget> media_depth;
  // With depth-aware upsampling: 1 at the layer texels on a depth edge the particles can see,
  // else 0 (R8, layer size; content/shaders/media_edges.frag).
  std::unique_ptr<gpu::RenderTarget> media_edges;
  // With media: per 8-pixel cell of the view, 1/z at the far and the near end of the view depths
  // z the frame's particles reach there (RG32F, systems/composite/particle_depth_grid.h), written
  // each frame by the composite system for depth-aware upsampling; 0 otherwise.
  gpu::Texture particle_depths;
  // Changes whenever the opaque pass draws the scene target's geometry (and depth) anew or copies
  // it back (the mesh_render system); a still camera's scene keeps it.
  uint64_t opaque_version = 0;
  // With media and depth-aware upsampling: per cell of particle_depths, the smallest window depth
  // of the scene target's opaque geometry (R32F; content/shaders/cell_nearest_depth.comp), and
  // the opaque_version it was made for (made again when that changes; none yet: the largest).
  gpu::Texture cell_nearest_depths;
  uint64_t cell_nearest_version = UINT64_MAX;
};

struct GpuFrame {
  std::vector<EyeTargets> eyes;
  std::unique_ptr<gpu::RenderTarget> output;   // GL_SRGB8_ALPHA8, at the views' size
  std::unique_ptr<gpu::RenderTarget> display;  // the output upscaled to full size, when the
                                               // frame scale is below 1 (else null)
  // Motion blur (RenderSettings::motion_blur > 0): the blended output in linear light
  // (RGBA16F, the output's size), and whether it holds a frame yet.
  std::unique_ptr<gpu::RenderTarget> history;
  bool history_valid = false;
};

}  // namespace pyro
