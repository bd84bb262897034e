// Every shipped scene renders, with its own lighting and shadows, the frame of its reference:
// frame 12 at 96x72 (`pyro render content/scenes/NAME.json --frames 12:12 --width 96 --height
// 72`), against tests/render/shipped_scenes_lit/NAME.png, which the same command rendered with the
// engine of the commit that last changed that scene's look (`git log` on the file names it). A
// change that should not change the pixels (moving code between folders, splitting a function)
// keeps these bytes. On the machine that rendered them the frames are byte-identical
// (the test prints whether they are; tools/compare_renders.sh checks every frame against any other
// checkout); llvmpipe's code follows the CPU it runs on, so elsewhere the values are held to
// within two levels of 255 with at most 0.5% of them differing at all, as for the frames of
// tests/render/frames_before_lighting_test.cpp. Scenes with a `quality` target are left out:
// their pick depends on timings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/frame_difference.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

const fs::path kLitSceneFrames = fs::path(PYRO_SOURCE_DIR) / "tests" / "render" / "shipped_scenes_lit";

class ShippedScenesLit : public testing::TestWithParam<std::string> {};

TEST_P(ShippedScenesLit, RendersItsReferenceFrame) {
  const std::string name = GetParam();
  // cloud_vdb.json reads the Disney cloud from the shared data, else its fallback: another frame.
  if (name == "cloud_vdb" && !fs::exists(fs::path(PYRO_SHARED_DATA_DIR) / "vdb" / "wdas_cloud_sixteenth.vdb"))
    GTEST_SKIP() << "cloud_vdb.json's frame is of " PYRO_SHARED_DATA_DIR "/vdb/wdas_cloud_sixteenth.vdb, absent here";
  const fs::path dir = test::scratch_dir("shipped_scenes_lit_" + name);
  const auto r = test::run_pyro({"render", test::scene_path(name + ".json"), "--frames", "12:12", "--width", "96",
                                 "--height", "72", "--out", dir.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path now = dir / "frame_0012.png", before = kLitSceneFrames / (name + ".png");
  test::FrameDifference diff;
  ASSERT_NO_FATAL_FAILURE(test::compare_frames(name, now, before, diff));
  EXPECT_LE(diff.largest, 2);
  EXPECT_LE(diff.share, 0.005);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, ShippedScenesLit,
                         testing::Values("campfire", "cloud_fitted", "cloud_vdb", "clouds", "explosion",
                                         "explosion_behind_tower", "explosion_dusk", "flipbook_fire",
                                         "flipbook_grid", "fog", "mist", "six_way_smoke", "smoke_stacks", "sunset",
                                         "vdb_fire"),
                         [](const auto& info) { return info.param; });

// Every reference frame is of a shipped scene, and every shipped scene without a quality target
// has one (a new scene adds its frame here).
TEST(ShippedScenesLit, EveryShippedSceneHasItsFrame) {
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(kLitSceneFrames)) {
    ++frames;
    EXPECT_TRUE(fs::exists(test::scene_path(entry.path().stem().string() + ".json"))) << entry.path();
  }
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PYRO_SOURCE_DIR) / "content" / "scenes")) {
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (entry.path().extension() == ".json" && text.find("\"quality\"") == std::string::npos) ++scenes;
  }
  EXPECT_GT(frames, 0);
  EXPECT_EQ(scenes, frames);
}

}  // namespace
}  // namespace pyro
