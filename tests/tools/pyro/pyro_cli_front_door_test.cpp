// Every command opens a scene through the one front door (systems/runtime/open_scene/open_scene.h): a
// scene with a quality target (content/scenes/fog_quality.json, small) runs under `pyro profile`
// and `pyro view` (its first load and a hot reload) with the settings `pyro render` picked. The
// pick is measured once, by the render, into a scratch cache; the others read it from there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/core/content_path.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"
#include "tests/support/xvfb.h"

namespace pyro {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

void write_scene_text(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

// The scene without its quality block (another length, so that an edit changes the file's stamp).
std::string without_target(std::string text) {
  const std::string block = "\n  \"quality\": {\"max_rmse\": 0.02},";
  const size_t at = text.find(block);
  EXPECT_NE(at, std::string::npos) << "fog_quality.json no longer sets its target as expected";
  if (at != std::string::npos) text.erase(at, block.size());
  return text;
}

class PyroCliFrontDoor : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratch_dir("front_door");
    scene_ = dir_ / "fog_quality.json";
    write_scene_text(scene_, read_text_file(test::scene_path("fog_quality.json")));
  }

  // `pyro` with the scratch cache, behind `launcher` (shell text, may be empty).
  test::CommandResult pyro(const std::string& launcher, std::vector<std::string> args) const {
    for (const char* size : {"--width", "64", "--height", "48"}) args.push_back(size);
    args.push_back("--json");
    return test::run_pyro_with(
        "env PYRO_CACHE_DIR=" + test::shell_quote((dir_ / "cache").string()) + " " + launcher,
        args);
  }

  // What `pyro render` reports of the pick it measured (the cache being empty).
  json rendered_pick() const {
    const auto r = pyro("", {"render", scene_.string(), "--out", (dir_ / "out").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("measuring"), std::string::npos) << r.err;
    const json summary = test::last_json_line(r.out);
    EXPECT_TRUE(summary.contains("quality")) << summary.dump();
    EXPECT_FALSE(summary["quality"]["from_cache"].get<bool>());
    return summary["quality"];
  }

  fs::path dir_, scene_;
};

// `report`'s pick is `rendered`, read from the cache, and its layer scale is the pick's.
void expect_same_pick(const json& report, const json& rendered) {
  ASSERT_TRUE(report.contains("quality")) << report.dump();
  const json& q = report["quality"];
  EXPECT_EQ(q["settings"], rendered["settings"]);
  EXPECT_EQ(q["max_rmse"], rendered["max_rmse"]);
  EXPECT_EQ(q["expected_rmse"], rendered["expected_rmse"]);
  EXPECT_TRUE(q["from_cache"].get<bool>());
  EXPECT_EQ(report["layer_scale"], rendered["settings"]["layer_scale"]);
}

TEST_F(PyroCliFrontDoor, ProfileRunsWithThePickRenderMade) {
  const json picked = rendered_pick();
  const auto r = pyro("", {"profile", scene_.string(), "--frames", "2", "--warmup", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("measuring"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pyro: quality: max RMSE 0.02 -> layer scale"), std::string::npos) << r.err;
  expect_same_pick(test::last_json_line(r.out), picked);
}

TEST_F(PyroCliFrontDoor, ViewRunsWithThePickRenderMadeOnLoadAndOnReload) {
  if (!test::have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const json picked = rendered_pick();
  const auto opened =
      pyro(test::xvfb_launcher(), {"view", scene_.string(), "--frames", "3", "--no-overlay"});
  ASSERT_EQ(opened.exit_code, 0) << opened.err;
  EXPECT_NE(opened.err.find("quality: max RMSE 0.02 -> layer scale"), std::string::npos)
      << opened.err;
  expect_same_pick(test::last_json_line(opened.out), picked);

  // Opened without a target, then edited to the targeted scene: the reload picks.
  const std::string targeted = read_text_file(scene_.string());
  write_scene_text(dir_ / "targeted.json", targeted);
  write_scene_text(scene_, without_target(targeted));
  const auto reloaded =
      pyro(test::xvfb_launcher(), {"view", scene_.string(), "--frames", "4", "--no-overlay",
                                   "--replace-at", "2:" + (dir_ / "targeted.json").string()});
  ASSERT_EQ(reloaded.exit_code, 0) << reloaded.err;
  const json report = test::last_json_line(reloaded.out);
  ASSERT_EQ(report["reloads"].size(), 1u) << report.dump();
  EXPECT_TRUE(report["reloads"][0]["ok"].get<bool>()) << report.dump();
  EXPECT_NE(reloaded.err.find("frame 2: quality: max RMSE 0.02"), std::string::npos)
      << reloaded.err;
  expect_same_pick(report, picked);
}

}  // namespace
}  // namespace pyro
