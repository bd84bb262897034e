// open_scene (systems/runtime/open_scene/open_scene.h) on a small Gaussian scene, with nothing measured:
// a pick handed in is the one the runtime runs with (layer scale, footprint table, substeps),
// offered to on_pick before the runtime exists and noted once; a scene without a target opens
// as written, whatever pick is handed in; a description handed in is not loaded again.
#include "systems/runtime/open_scene/open_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "systems/runtime/scene/scene_loader.h"
#include "tests/support/small_runtime.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// 40 Gaussian particles; the default footprint table (64) and layers at full resolution.
std::string small_fog(bool with_target) {
  return std::string("{\"name\": \"small fog\", \"seed\": 3,") +
         " \"output\": {\"width\": 48, \"height\": 48, \"fps\": 30}," +
         (with_target ? " \"quality\": {\"max_rmse\": 0.05}," : "") +
         " \"camera\": {\"position\": [0, 1, 6], \"target\": [0, 1, 0], \"fov_y_deg\": 45},"
         " \"clouds\": [{\"count\": 40, \"radius\": 0.5, \"density\": 0.3, \"color\": 0.8,"
         " \"box\": {\"min\": [-1, 0.5, -1], \"max\": [1, 1.5, 1]}}]}";
}

SceneDescription load_text(const std::string& name, const std::string& text) {
  const fs::path file = test::scratch_dir("open_scene_" + name) / "scene.json";
  std::ofstream(file) << text;
  return load_scene(file.string());
}

QualityPick half_scale_pick() {
  QualityPick pick;
  pick.max_rmse = 0.05;
  pick.settings = {0.5f, 16, 2, std::nullopt};
  pick.expected_rmse = 0.01;
  pick.met = true;
  pick.from_cache = true;
  return pick;
}

TEST(OpenScene, AHandedInPickIsTheOneTheRuntimeRunsWith) {
  const SceneDescription scene = load_text("pick", small_fog(true));
  ASSERT_EQ(scene.footprint.size, 64);
  OpenSceneOptions open;
  open.runtime = test::small_runtime();
  open.description = scene;
  open.quality = half_scale_pick();
  std::vector<std::string> notes;
  open.on_note = [&notes](const std::string& n) { notes.push_back(n); };
  int picks_seen = 0;
  open.on_pick = [&picks_seen](const std::optional<QualityPick>& p) {
    ++picks_seen;
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->settings.footprint_size, 16);
  };
  const OpenedScene opened = open_scene("not read: the description is handed in", open);
  EXPECT_EQ(picks_seen, 1);
  ASSERT_TRUE(opened.quality.has_value());
  EXPECT_EQ(opened.quality->settings, half_scale_pick().settings);
  const ResolvedScene& r = opened.runtime->resolved();
  EXPECT_FLOAT_EQ(r.settings.layer_scale, 0.5f);
  EXPECT_EQ(r.scene.footprint.size, 16);
  EXPECT_EQ(r.substeps, 2);
  EXPECT_FLOAT_EQ(r.scene.frames_per_second, 60.0f);  // 30 fps, 2 steps per frame
  EXPECT_EQ(opened.description.footprint.size, 64);   // the description as loaded
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], quality_pick_note(half_scale_pick(), scene));
}

TEST(OpenScene, ASceneWithoutATargetOpensAsWritten) {
  const SceneDescription scene = load_text("no_target", small_fog(false));
  OpenSceneOptions open;
  open.runtime = test::small_runtime();
  open.quality = half_scale_pick();  // no target: not applied
  std::vector<std::optional<QualityPick>> seen;
  open.on_pick = [&seen](const std::optional<QualityPick>& p) { seen.push_back(p); };
  const OpenedScene opened = open_scene(scene.file, open);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_FALSE(seen[0].has_value());
  EXPECT_FALSE(opened.quality.has_value());
  EXPECT_EQ(opened.description.content_digest, scene.content_digest);  // loaded from the path
  const ResolvedScene& r = opened.runtime->resolved();
  EXPECT_FALSE(r.quality.has_value());
  EXPECT_FLOAT_EQ(r.settings.layer_scale, 1.0f);
  EXPECT_EQ(r.scene.footprint.size, 64);
  EXPECT_EQ(r.substeps, 1);
}

}  // namespace
}  // namespace pyro
