#pragma once
// GPU state of the composite phase: the reduced-resolution particle layer upsampled over the
// scene, and the views composed into the output image for the chosen stereo mode.
#include "components/gpu_frame.h"
#include "components/render_settings.h"
#include "engine/gpu/gl_objects.h"
#include "engine/math/detail_noise.h"
#include "systems/composite/compose_tiles.h"

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

namespace pyro {

// How explosion media layers are composed (Umenhoffer et al. 2006, section 4).
struct MediaComposition {
  float near = 0.1f, far = 100.0f;  // the views' clip distances, for view depth
  float time = 0.0f;                // seconds, animates the shimmer's noise (one period a second)
  float shimmer = 0.0f;             // scene offset per unit fire opacity (fraction of the view)
  // Depth-aware upsampling (content/shaders/compose.frag, upsampled_media): bilinear where the
  // layer's texels saw the pixel's surface, their weights changed across depth edges; false:
  // bilinear everywhere.
  bool depth_aware = true;
  // The difference of clip depths (depths clamped to the views' EyeTargets::particle_depths, as
  // a share of their extent) up to which a texel counts as having seen the pixel's surface.
  float depth_tolerance = 0.15f;
  // Compose in screen tiles sorted by the work they need (systems/composite/compose_tiles.h);
  // false: every pixel runs the full variant (the same image, slower; for tests and comparison).
  bool tiles = true;
};

// Where a view's tiles without media may be copied from its scene (textures of one format), or
// 0: drawn with the scene-only variant.
struct SceneCopy {
  GLuint from = 0, to = 0;
};

class Compositor {
 public:
  Compositor();
  void set_media(const MediaComposition& m) { media_ = m; }
  // Alpha out as the coverage (the TRANSPARENT variants of compose.frag), else 1.
  void set_transparent(bool transparent) { transparent_ = transparent; }
  // Writes one view, its layer composited, into the linear float target `out` (same size):
  // the final composition's arithmetic without the sRGB encoding, for readback.
  void resolve_linear(const EyeTargets& view, const gpu::RenderTarget& out);
  // Writes frame.output from the views in frame.eyes (left, right) for `mode`, compositing each
  // view's particle layer over its scene on the way: one full-screen pass in all.
  // `swap_eyes`: the right view goes where the left one is expected, and the other way round.
  // `motion_blur` b > 0 (frame.history set): the views are blended into frame.history as
  // (1 - b) new + b history (the first frame replaces it), which is then encoded into
  // frame.output.
  void compose(StereoMode mode, GpuFrame& frame, bool swap_eyes = false, float motion_blur = 0.0f);

 private:
  // Binds the views' textures (the same units for every variant of compose.frag).
  void bind_views(const EyeTargets& left, const EyeTargets& right);
  // Explosion media: the three layers composited, and their depths, at layer size; `edges`: the
  // texels on depth edges marked (mark_edges).
  void prepare_media(EyeTargets& eye, bool edges);
  // EyeTargets::media_edges from media_depth and the particle depths (media_edges.frag), and
  // EyeTargets::cell_nearest_depths when the opaque scene changed.
  void mark_edges(EyeTargets& eye);
  // EyeTargets::cell_nearest_depths from the scene target's depth (cell_nearest_depth.comp).
  void find_cell_nearest_depths(EyeTargets& eye);
  // One full-screen draw with the compose.frag variant for these matrices (a zero matrix
  // compiles that view out) and the bound views' kind (plain, layers, media).
  // With media, the draw is split into tiles (list set `slot`: one per view of a frame).
  void draw_view(const glm::mat3& left_matrix, const glm::mat3& right_matrix, int x, int y,
                 int width, int height, int slot = 0, const SceneCopy& copy = {});
  // What a compose.frag variant does beyond reading the scene, for the bound views' kind.
  struct Features {
    bool media = true;        // with media bound: composite them (false: the scene alone)
    bool depth_aware = false;
    bool front = false;       // no media where the surface is nearer than every particle
    bool full_size = false;   // layers at the view's size: read texel for texel
    bool shimmer = false;
    bool tiled = false;       // linked with compose_tile.vert instead of fullscreen.vert
  };
  const gpu::Program& variant(bool use_left, bool use_right, const Features& features);
  void upload_shimmer_noise(float time);

  std::array<gpu::Program, 2048> compose_;  // compose.frag variants, compiled on first use
  gpu::Program media_prepare_, media_edges_, cell_nearest_depth_;
  gpu::Framebuffer prepare_fbo_;  // two outputs: media_combined and media_depth
  gpu::VertexArray empty_;
  MediaComposition media_;
  bool layers_ = false, media_bound_ = false;  // what bind_views bound
  // The draws write the sRGB output's bytes themselves (srgb_encode.glsl, GL_FRAMEBUFFER_SRGB
  // off): cheaper than GL's conversion on llvmpipe. Set by compose for its draws.
  bool encode_ = false;
  bool transparent_ = false;
  glm::ivec2 media_layer_size_{0};              // with media bound: the layers' size
  ComposeTiles tiles_;
  DetailNoise shimmer_volume_;    // made on first use
  gpu::Texture shimmer_noise_;    // its slice at the frame's time (two channels)
  float shimmer_noise_time_ = -1.0f;
};

}  // namespace pyro
