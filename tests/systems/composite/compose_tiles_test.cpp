// The final pass in tiles sorted by the work they need (systems/composite/compose_tiles.h)
// against the full variant on every pixel, on the paper's explosion at 1/8 and 1/2 resolution
// layers, mono (the linear readback and the sRGB output, whose tiles without media are copied)
// and in the two stereo paths (side by side: a list per view; anaglyph: both eyes in one draw).
// Tiles without media, and tiles without fire, are the same image by construction (to a byte);
// tiles the classifier finds free of depth edges keep the bilinear sample where the per-pixel
// depth-aware test could still reweight the texels (geometry the layer never saw), so the bound there
// is on the RMSE and on the share of pixels that differ.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "components/explosion_shading.h"
#include "components/frame_image.h"
#include "components/gpu_frame.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/composite/compose_tiles.h"
#include "systems/composite/compositor.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"

namespace pyro {
namespace {

struct ComposeTilesFrames {
  std::vector<float> linear;     // the first view, linear
  std::vector<uint8_t> output;   // the sRGB output target
};

ComposeTilesFrames render_compose_tiles(float layer_scale, StereoMode mode, bool tiles) {
  const SceneDescription scene = load_scene(std::string(PYRO_SOURCE_DIR) + "/content/scenes/explosion.json");
  RuntimeOptions o;
  o.width_override = o.height_override = 256;
  o.layer_scale = layer_scale;
  o.stereo_mode = mode;
  SceneRuntime run(scene, o);
  MediaComposition m;
  m.tiles = tiles;
  run.world().set_resource<MediaComposition>(m);
  for (int f = 0; f < 12; ++f) run.step();  // the explosion under way: fire, smoke and dust
  return {run.image().rgba, run.world().resource<GpuFrame>().output->read_rgba8()};
}

struct Difference {
  double rmse = 0.0;
  double share_over_one_step = 0.0;  // pixels differing by more than one 8-bit step
};

template <typename T>
Difference compare_compose_tiles(const std::vector<T>& a, const std::vector<T>& b, double step) {
  EXPECT_EQ(a.size(), b.size());
  double sum = 0.0;
  size_t over = 0;
  for (size_t i = 0; i < a.size(); i += 4) {
    bool differs = false;
    for (size_t c = 0; c < 3; ++c) {
      const double d = (static_cast<double>(a[i + c]) - static_cast<double>(b[i + c])) / (step * 255.0);
      sum += d * d;
      differs = differs || std::abs(d) * 255.0 > 1.0 + 1e-6;
    }
    over += differs;
  }
  const double pixels = static_cast<double>(a.size() / 4);
  return {std::sqrt(sum / (3.0 * pixels)), over / pixels};
}

TEST(ComposeTiles, GridCoversTheViewInWholeTiles) {
  for (int layer : {512, 256, 128, 64}) {
    const ComposeTiles::Grid g = ComposeTiles::grid_for({512, 512}, {layer, layer});
    EXPECT_EQ(g.tiles, glm::ivec2(512 / ComposeTiles::tile_pixels)) << layer;
    EXPECT_FLOAT_EQ(g.texels_per_pixel.x, layer / 512.0f) << layer;
  }
  // A view the tile does not divide: the last column and row reach past it, none is left out.
  const ComposeTiles::Grid odd = ComposeTiles::grid_for({300, 200}, {38, 25});
  EXPECT_GE(odd.tiles.x * ComposeTiles::tile_pixels, 300);
  EXPECT_LT((odd.tiles.x - 1) * ComposeTiles::tile_pixels, 300);
  EXPECT_GE(odd.tiles.y * ComposeTiles::tile_pixels, 200);
  EXPECT_LT((odd.tiles.y - 1) * ComposeTiles::tile_pixels, 200);
  EXPECT_THROW(ComposeTiles::grid_for({64, 64}, {65, 64}), std::invalid_argument);
  EXPECT_THROW(ComposeTiles::grid_for({0, 64}, {0, 64}), std::invalid_argument);
}

TEST(ComposeTiles, TiledImageMatchesTheFullVariantMono) {
  for (float scale : {0.125f, 0.5f}) {
    const ComposeTilesFrames tiled = render_compose_tiles(scale, StereoMode::mono, true);
    const ComposeTilesFrames full = render_compose_tiles(scale, StereoMode::mono, false);
    const Difference linear = compare_compose_tiles(tiled.linear, full.linear, 1.0 / 255.0);
    const Difference srgb = compare_compose_tiles(tiled.output, full.output, 1.0);
    EXPECT_LT(linear.rmse, 2e-3) << scale;
    EXPECT_LT(linear.share_over_one_step, 0.01) << scale;
    EXPECT_LT(srgb.rmse, 2e-3) << scale;
    EXPECT_LT(srgb.share_over_one_step, 0.01) << scale;
  }
}

TEST(ComposeTiles, TiledImageMatchesTheFullVariantInStereo) {
  for (StereoMode mode : {StereoMode::side_by_side, StereoMode::anaglyph}) {
    const ComposeTilesFrames tiled = render_compose_tiles(0.125f, mode, true);
    const ComposeTilesFrames full = render_compose_tiles(0.125f, mode, false);
    const Difference srgb = compare_compose_tiles(tiled.output, full.output, 1.0);
    EXPECT_LT(srgb.rmse, 2e-3) << static_cast<int>(mode);
    EXPECT_LT(srgb.share_over_one_step, 0.01) << static_cast<int>(mode);
  }
}

// Bilinear upsampling and no shimmer: only "media" and "scene alone" tiles, both exact. The views
// are sized so that the tiles do not divide them, side by side as well: a pixel left out or a
// tile spilling into the other view would show.
std::vector<uint8_t> render_plain(glm::ivec2 size, StereoMode mode, bool tiles) {
  const SceneDescription scene = load_scene(std::string(PYRO_SOURCE_DIR) + "/content/scenes/explosion.json");
  RuntimeOptions o;
  o.width_override = size.x;
  o.height_override = size.y;
  o.layer_scale = 0.25f;
  o.stereo_mode = mode;
  SceneRuntime run(scene, o);
  MediaComposition m;
  m.tiles = tiles;
  m.depth_aware = false;
  run.world().set_resource<MediaComposition>(m);
  ExplosionShading shading;
  shading.shimmer = 0.0f;
  run.world().set_resource<ExplosionShading>(shading);
  for (int f = 0; f < 8; ++f) run.step();
  return run.world().resource<GpuFrame>().output->read_rgba8();
}

TEST(ComposeTiles, WithoutTheFeaturesTheClassesNeedTheImageIsExact) {
  for (StereoMode mode : {StereoMode::mono, StereoMode::side_by_side}) {
    for (glm::ivec2 size : {glm::ivec2(192, 192), glm::ivec2(203, 141)}) {
      const std::vector<uint8_t> tiled = render_plain(size, mode, true);
      const std::vector<uint8_t> full = render_plain(size, mode, false);
      const Difference d = compare_compose_tiles(tiled, full, 1.0);
      EXPECT_EQ(d.share_over_one_step, 0.0) << size.x << " " << static_cast<int>(mode);
      EXPECT_LT(d.rmse, 1.0 / 255.0) << size.x << " " << static_cast<int>(mode);
    }
  }
}

}  // namespace
}  // namespace pyro
