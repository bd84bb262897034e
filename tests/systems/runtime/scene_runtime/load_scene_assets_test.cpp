// The runtime's second layer alone: volumes read and noted, the budget checked again with their
// particles, flipbooks shared between fires that prepare them alike, all before any world exists
// (no world is made in these tests); the engine's default flipbook baked when missing by the front
// door (prepare_scene_run) before any runtime, and refused unbaked by the runtime alone.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/user_error.h"
#include "engine/io/particle_file.h"
#include "engine/io/png_file.h"
#include "systems/flipbook_fire/flipbook_folder.h"
#include "systems/runtime/open_scene/flipbook_bake.h"
#include "systems/runtime/open_scene/open_scene.h"
#include "systems/runtime/scene/scene_loader.h"
#include "systems/runtime/scene_runtime/load_scene_assets.h"
#include "systems/runtime/scene_runtime/resolve_scene.h"
#include "systems/runtime/scene_runtime/scene_asset_cache.h"
#include "systems/runtime/scene_runtime/scene_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

ResolvedScene resolved(const std::string& path) {
  return resolve_scene(load_scene(path), RuntimeOptions{}, 4096);
}

// A scene with one volume of `n` particles from a particle file, and `budget` particles.
std::string volume_scene(const fs::path& dir, size_t n, const std::string& budget = "") {
  ParticleFile file;
  for (size_t i = 0; i < n; ++i) file.particles.push_back({float(i), 0, 0, 0.5f, 0.3f, 1, 1, 1});
  write_particle_file((dir / "dots.pyrop").string(), file);
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"volumes": [{"file": "dots.pyrop"}])" + budget + "}";
  return path;
}

TEST(LoadSceneAssets, ReadsVolumesAndNotesWhichFile) {
  const fs::path dir = test::scratch_dir("assets_volume");
  std::vector<std::string> sunk;
  const SceneAssets assets =
      load_scene_assets(resolved(volume_scene(dir, 7)), [&](const std::string& n) { sunk.push_back(n); });
  ASSERT_EQ(assets.volumes.size(), 1u);
  EXPECT_EQ(assets.volumes[0].particles.size(), 7u);
  EXPECT_EQ(assets.volumes[0].source.particles, 7u);
  // Placed about the bounding box's centre (the default anchor) at scale 1: 0 .. 6 becomes -3 .. 3.
  EXPECT_FLOAT_EQ(assets.volumes[0].particles.px[0], -3.0f);
  EXPECT_FLOAT_EQ(assets.volumes[0].particles.px[6], 3.0f);
  ASSERT_EQ(assets.notes.size(), 1u);
  EXPECT_NE(assets.notes[0].find("/volumes/0: using volume file"), std::string::npos) << assets.notes[0];
  EXPECT_EQ(sunk, assets.notes);
}

TEST(LoadSceneAssets, RefusesVolumesOverTheParticleBudget) {
  const fs::path dir = test::scratch_dir("assets_budget");
  // Resolving cannot know the volume's particles; the assets step refuses once it has read them.
  const ResolvedScene r = resolved(volume_scene(dir, 9, R"(, "budget": {"particles": 8})"));
  try {
    load_scene_assets(r);
    FAIL() << "9 volume particles passed a budget of 8";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("/budget/particles"), std::string::npos) << e.what();
  }
  EXPECT_EQ(load_scene_assets(resolved(volume_scene(dir, 8, R"(, "budget": {"particles": 8})")))
                .volumes.size(),
            1u);
}

// A folder of `frames` 4x4 grey PNG frames.
void write_flipbook(const fs::path& dir, int frames) {
  fs::create_directories(dir);
  for (int f = 0; f < frames; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", f);
    write_png((dir / name).string(), 4, 4, 3, std::vector<uint8_t>(4 * 4 * 3, uint8_t(60 + f)));
  }
}

std::string fire(const std::string& folder, const std::string& preparation) {
  return R"({"flipbook": ")" + folder + R"(", "preparation": )" + preparation + "}";
}

TEST(LoadSceneAssets, FiresPreparedAlikeShareTheirFrames) {
  const fs::path dir = test::scratch_dir("assets_fires");
  const fs::path book = dir / "book";
  write_flipbook(book, 3);
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"fires": [)" + fire("book", R"({"soften": 0.2})") + ", " +
                             fire("book", R"({"soften": 0.2})") + ", " +
                             fire("book", R"({"soften": 0.4})") + "]}";
  const SceneAssets assets = load_scene_assets(resolved(path));
  ASSERT_EQ(assets.fires.size(), 3u);
  EXPECT_EQ(assets.flipbooks.frames.size(), 2u);
  EXPECT_EQ(assets.flipbooks.fire_frames, (std::vector<size_t>{0, 0, 1}));
  EXPECT_EQ(assets.flipbooks.frames[0].rgba.size(), 3u);
}

class FlipbookDir {  // PYRO_FLIPBOOK_DIR set for the test's lifetime
 public:
  explicit FlipbookDir(const std::string& dir) {
    if (const char* v = std::getenv("PYRO_FLIPBOOK_DIR")) saved_ = v, had_ = true;
    setenv("PYRO_FLIPBOOK_DIR", dir.c_str(), 1);
  }
  ~FlipbookDir() {
    if (had_) setenv("PYRO_FLIPBOOK_DIR", saved_.c_str(), 1);
    else unsetenv("PYRO_FLIPBOOK_DIR");
  }

 private:
  std::string saved_;
  bool had_ = false;
};

TEST(LoadSceneAssets, TheFrontDoorBakesAMissingDefaultFlipbookBeforeAnyRuntime) {
  const fs::path dir = test::scratch_dir("assets_bake");
  const FlipbookDir env((dir / "fire").string());
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"fires": [{"name": "default"}]})";
  std::vector<std::string> notes;
  SceneAssetCache cache;
  RuntimeOptions options;
  options.on_note = [&](const std::string& n) { notes.push_back(n); };
  options.asset_cache = &cache;
  prepare_scene_run(load_scene(path), options);
  EXPECT_TRUE(fs::is_regular_file(dir / "fire" / "flipbook.json"));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("baking the default flame flipbook"), std::string::npos) << notes[0];
  EXPECT_EQ(cache.counters().flipbooks_baked, 1u);
  // The runtime's asset step then only reads the folder, and notes nothing.
  const SceneAssets assets = load_scene_assets(resolved(path));
  ASSERT_EQ(assets.fires.size(), 1u);
  EXPECT_EQ(assets.fires[0].flipbook, (dir / "fire").string());
  EXPECT_TRUE(assets.notes.empty());
  EXPECT_EQ(assets.flipbooks.frames.at(0).rgba.size(), size_t(FlipbookBakeOptions{}.frames));
  // Baked once: preparing again bakes nothing and notes nothing.
  prepare_scene_run(load_scene(path), options);
  EXPECT_EQ(notes.size(), 1u);
  EXPECT_EQ(cache.counters().flipbooks_baked, 1u);
}

TEST(LoadSceneAssets, TheRuntimeAloneRefusesAnUnbakedDefaultFlipbook) {
  const fs::path dir = test::scratch_dir("assets_unbaked");
  const fs::path empty = dir / "fire";
  fs::create_directories(empty);
  const FlipbookDir env(empty.string());
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"fires": [{"name": "default"}]})";
  const auto expect_refused = [&](const std::function<void()>& load) {
    try {
      load();
      ADD_FAILURE() << "a fire without a flipbook loaded with the default flipbook unbaked";
    } catch (const UserError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.file(), empty.string());
      EXPECT_NE(what.find("a baked default flame flipbook: scenes opened through the front door "
                          "(systems/runtime/open_scene/open_scene.h) bake it first, as does the "
                          "build's default_flipbook target"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("/fires/0"), std::string::npos) << what;
    }
  };
  expect_refused([&] { load_scene_assets(resolved(path)); });
  // SceneRuntime itself, opened without the front door: refused by its asset step, before any world.
  expect_refused([&] { SceneRuntime runtime(load_scene(path)); });
  EXPECT_TRUE(fs::is_empty(empty));  // nothing baked behind the front door
}

}  // namespace
}  // namespace pyro
