// Assets kept across rebuilds: an edit that touches no volume or flipbook reads neither again
// (the cache's counters), the world built from kept assets draws the same image as one built from
// files, and an edit of what a volume's import reads imports it again.
#include "systems/runtime/scene_runtime/scene_asset_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "components/frame_image.h"
#include "components/volume_source.h"
#include "engine/io/png_file.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/density_ball.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// A soft ball of density, 8^3 voxels of 0.25 world units about the origin.
void write_cached_ball(const std::string& path) { test::write_density_ball(path, 8, 3.6, 0.25, -1.0); }

// A flipbook folder of 3 frames, 8x8, a warm gradient.
void write_cached_flipbook(const fs::path& dir) {
  fs::create_directories(dir);
  for (int f = 0; f < 3; ++f) {
    std::vector<uint8_t> rgb(8 * 8 * 3);
    for (int i = 0; i < 64; ++i) {
      rgb[3 * i] = uint8_t(120 + 10 * f + i);
      rgb[3 * i + 1] = uint8_t(40 + i);
      rgb[3 * i + 2] = 10;
    }
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    write_png((dir / name).string(), 8, 8, 3, rgb);
  }
}

// A volume, an emitter and two fires (one with its own flipbook, one with the engine's).
std::string cached_scene_text(float volume_error, float emitter_rate) {
  return R"({"background": [0.2, 0.3, 0.5],
    "camera": {"position": [0, 0.5, 7], "target": [0, 0.5, 0], "fov_y_deg": 40},
    "light": {"direction": [0, -1, 0], "color": [1, 1, 1], "ambient": [0.2, 0.2, 0.2]},
    "volumes": [{"file": "ball.vdb", "error": )" + std::to_string(volume_error) + R"(}],
    "emitters": [{"name": "puff", "medium": "smoke", "budget": 200, "seed": 4, "rate": )" +
         std::to_string(emitter_rate) + R"(,
      "shape": {"type": "sphere", "position": [1.5, 0, 0], "radius": 0.3},
      "lifetime": 2, "size": 0.2, "density": 0.5}],
    "fires": [{"name": "own", "flipbook": "book", "position": [-1.5, -1, 0], "width": 0.8},
              {"name": "default", "position": [0, -1, 1], "width": 0.6}]})";
}

struct CachedScene {
  fs::path dir;
  std::string path;
  void write(float volume_error, float emitter_rate) const {
    std::ofstream(path) << cached_scene_text(volume_error, emitter_rate);
  }
};

CachedScene make_cached_scene(const std::string& name) {
  CachedScene s{test::scratch_dir(name), ""};
  s.path = (s.dir / "scene.json").string();
  write_cached_ball((s.dir / "ball.vdb").string());
  write_cached_flipbook(s.dir / "book");
  return s;
}

OpenSceneOptions cached_scene_options(SceneAssetCache* cache) {
  OpenSceneOptions o;
  o.runtime.width_override = 48;
  o.runtime.height_override = 48;
  o.runtime.asset_cache = cache;
  return o;
}

// Frame 4 of `path`, with or without a cache.
std::vector<float> cached_scene_image(const std::string& path, SceneAssetCache* cache) {
  OpenedScene opened = open_scene(path, cached_scene_options(cache));
  opened.runtime->draw_frame(4);
  return opened.runtime->image().rgba;
}

uint64_t volume_particles(const std::string& path, SceneAssetCache* cache) {
  OpenedScene opened = open_scene(path, cached_scene_options(cache));
  uint64_t n = 0;
  opened.runtime->world().each<VolumeSource>([&](VolumeSource& s) { n += s.particles; });
  return n;
}

TEST(SceneAssetCache, AnEmitterEditReadsNoVolumeOrFlipbookAgain) {
  const CachedScene scene = make_cached_scene("asset_cache_emitter");
  scene.write(0.05f, 40.0f);
  SceneAssetCache cache;
  cached_scene_image(scene.path, &cache);
  SceneAssetCounters c = cache.counters();
  EXPECT_EQ(c.volumes_loaded, 1u);
  EXPECT_EQ(c.volumes_reused, 0u);
  EXPECT_EQ(c.flipbooks_prepared, 2u);  // the fire's own and the engine's
  EXPECT_EQ(c.flipbooks_reused, 0u);
  EXPECT_EQ(c.flipbooks_baked, 0u);     // the build baked the engine's flipbook

  scene.write(0.05f, 90.0f);  // the emitter's rate
  const std::vector<float> kept = cached_scene_image(scene.path, &cache);
  c = cache.counters();
  EXPECT_EQ(c.volumes_loaded, 1u);
  EXPECT_EQ(c.volumes_reused, 1u);
  EXPECT_EQ(c.flipbooks_prepared, 2u);
  EXPECT_EQ(c.flipbooks_reused, 2u);
  EXPECT_EQ(c.flipbooks_baked, 0u);

  const std::vector<float> read = cached_scene_image(scene.path, nullptr);
  ASSERT_EQ(kept.size(), read.size());
  EXPECT_TRUE(kept == read) << "the world built from kept assets draws another image";
  double sum = 0.0;
  for (const float v : kept) sum += v;
  EXPECT_GT(sum, 0.0);
}

TEST(SceneAssetCache, AVolumeEditImportsAgainAndOnlyTheLastLoadIsKept) {
  const CachedScene scene = make_cached_scene("asset_cache_volume");
  scene.write(0.02f, 40.0f);
  SceneAssetCache cache;
  const uint64_t fine = volume_particles(scene.path, &cache);
  scene.write(0.2f, 40.0f);  // the import's error target: another particle count
  const uint64_t coarse = volume_particles(scene.path, &cache);
  EXPECT_EQ(cache.counters().volumes_loaded, 2u);
  EXPECT_EQ(cache.counters().volumes_reused, 0u);
  EXPECT_EQ(cache.counters().flipbooks_reused, 2u);
  EXPECT_EQ(coarse, volume_particles(scene.path, nullptr));
  EXPECT_NE(fine, coarse);

  scene.write(0.02f, 40.0f);  // back: the first import was dropped by the second load
  EXPECT_EQ(volume_particles(scene.path, &cache), fine);
  EXPECT_EQ(cache.counters().volumes_loaded, 3u);

  write_cached_ball((scene.dir / "ball.vdb").string());  // the file rewritten: a new stamp
  volume_particles(scene.path, &cache);
  EXPECT_EQ(cache.counters().volumes_loaded, 4u);
}

}  // namespace
}  // namespace pyro
