// Scripted authoring in pyro view, under a virtual X server (skipped with a message without
// xvfb-run): values set through the scene document as the inspector sets them, one undone, the
// result saved as a new file that differs from the original in exactly the two kept values (the
// rest of the text byte for byte), renders headless to the viewer's screenshot, and re-read no
// volume on the way. A value the loader refuses ends the session with its message, nothing saved.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/particle_file.h"
#include "engine/io/png_file.h"
#include "tests/support/file_bytes.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"
#include "tests/support/xvfb.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;
using Args = std::vector<std::string>;

// Pretty-printed by hand, with texts a re-serialiser would change ("0.40", the layout).
const char* kAuthoringScene = R"({
  "name": "authoring",
  "seed": 7,
  "output": {"width": 96, "height": 72, "fps": 30},
  "background": [0.5, 0.6, 0.7],
  "camera": {"position": [0.0, 1.5, 9.0], "target": [0.0, 1.5, 0.0], "fov_y_deg": 45},
  "light": {"direction": [-0.6, -0.8, -0.4], "color": [1.0, 0.95, 0.85], "ambient": [0.18, 0.2, 0.25]},
  "clouds": [{"name": "puff", "count": 300, "radius": 0.5, "density": 0.40, "color": 0.9,
              "box": {"min": [-3.0, 0.5, -1.0], "max": [0.0, 2.5, 1.0]}, "seed": 3}],
  "volumes": [{"file": "blob.pyrop", "position": [2.0, 1.5, 0.0]}],
  "emitters": [{"name": "plume", "medium": "smoke", "budget": 400, "seed": 4,
                "shape": {"type": "disc", "position": [0.5, 0.2, 0.0], "radius": 0.3},
                "rate": 60, "direction": [0.0, 1.0, 0.0], "speed": {"min": 0.5, "max": 0.8},
                "size": {"min": 0.25, "max": 0.35}, "lifetime": 3, "density": 0.5,
                "color": [0.2, 0.2, 0.2],
                "dynamics": {"gravity_scale": 0.0}}]
}
)";

fs::path write_authoring_scene(const fs::path& dir) {
  ParticleFile blob;
  for (int i = 0; i < 20; ++i)
    blob.particles.push_back({0.05f * float(i % 5), 0.05f * float(i / 5), 0.0f, 0.4f, 0.6f, 0.9f, 0.5f, 0.3f});
  write_particle_file((dir / "blob.pyrop").string(), blob);
  const fs::path scene = dir / "scene.json";
  std::ofstream(scene, std::ios::binary) << kAuthoringScene;
  return scene;
}

// Every leaf pointer whose value differs between a and b (present in one only counts).
void differing_leaves(const nlohmann::json& a, const nlohmann::json& b, const std::string& at,
                      std::set<std::string>& out) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [k, v] : a.items())
      if (b.contains(k)) differing_leaves(v, b[k], at + "/" + k, out); else out.insert(at + "/" + k);
    for (const auto& [k, v] : b.items())
      if (!a.contains(k)) out.insert(at + "/" + k);
  } else if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (size_t i = 0; i < a.size(); ++i) differing_leaves(a[i], b[i], at + "/" + std::to_string(i), out);
  } else if (a != b) {
    out.insert(at);
  }
}

std::string replaced_once(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(PyroViewAuthoring, SetUndoSaveAsKeepsTwoEditsAndRendersAsTheViewerShowed) {
  if (!test::have_xvfb_run()) GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("view_authoring");
  const fs::path scene = write_authoring_scene(dir);
  const fs::path saved = dir / "tuned.json", shot = dir / "shot.png";
  const auto r = test::run_pyro_with(
      test::xvfb_launcher(),
      {"view", scene.string(), "--frames", "12", "--no-overlay", "--set-at", "3:/clouds/0/density=0.8",
       "--set-at", "5:/emitters/0/rate=120", "--set-at", "7:/light/direction=[0.3, -1, 0.2]",
       "--undo-at", "9", "--screenshot-at", "11:" + shot.string(), "--save-as", saved.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = test::last_json_line(r.out);
  EXPECT_EQ(summary["edits"], 4);  // three sets and an undo, each a new runtime
  // The cloud's density and the emitter's rate reused the imported volume; the light direction
  // (the import bakes the light into the particles) and its undo imported it again.
  EXPECT_EQ(summary["assets"]["volumes_loaded"], 3) << summary.dump();
  EXPECT_EQ(summary["assets"]["volumes_reused"], 2) << summary.dump();

  // Exactly the two kept values differ; the rest of the text is byte for byte the original's.
  const std::string original = kAuthoringScene, tuned = test::read_bytes(saved);
  std::set<std::string> changed;
  differing_leaves(nlohmann::json::parse(original), nlohmann::json::parse(tuned), "", changed);
  EXPECT_EQ(changed, (std::set<std::string>{"/clouds/0/density", "/emitters/0/rate"}));
  EXPECT_EQ(tuned, replaced_once(replaced_once(original, "\"density\": 0.40", "\"density\": 0.8"),
                                 "\"rate\": 60", "\"rate\": 120"));
  EXPECT_EQ(test::read_bytes(scene), original);  // save-as leaves the original alone

  // The saved file, rendered headless, is the viewer's frame 11.
  const auto h = test::run_pyro({"render", saved.string(), "--frames", "12", "--out", (dir / "headless").string()});
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const PngImage ref = read_png((dir / "headless" / "frame_0011.png").string());
  const PngImage got = read_png(shot.string());
  ASSERT_EQ(ref.pixels.size(), got.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < ref.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(ref.pixels[i]) - int(got.pixels[i])));
  EXPECT_LE(worst, 2);
  // And the edits showed: the original scene's frame 11 is another image.
  const auto o = test::run_pyro({"render", scene.string(), "--frames", "12", "--out", (dir / "original").string()});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const PngImage before = read_png((dir / "original" / "frame_0011.png").string());
  int moved = 0;
  for (size_t i = 0; i < before.pixels.size(); ++i) moved += std::abs(int(before.pixels[i]) - int(got.pixels[i])) > 8;
  EXPECT_GT(moved, 30);
}

TEST(PyroViewAuthoring, ARefusedValueEndsTheSessionWithTheLoadersMessageAndSavesNothing) {
  if (!test::have_xvfb_run()) GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("view_authoring_refused");
  const fs::path scene = write_authoring_scene(dir);
  const fs::path saved = dir / "never.json";
  for (const std::string& set : {std::string("2:/clouds/0/density=7"), std::string("2:/clouds/0/densty=0.5"),
                                 std::string("2:/clouds/4/density=0.5")}) {
    const auto r = test::run_pyro_with(test::xvfb_launcher(),
                                       {"view", scene.string(), "--frames", "4", "--no-overlay", "--set-at", set,
                                        "--save-as", saved.string()});
    EXPECT_EQ(r.exit_code, 2) << set << "\n" << r.err;
    EXPECT_NE(r.err.find(scene.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/clouds/"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(saved)) << set;
  }
  EXPECT_EQ(test::read_bytes(scene), kAuthoringScene);
  // A malformed request is refused before the window opens.
  const auto bad = test::run_pyro({"view", scene.string(), "--set-at", "2:clouds=1"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("FRAME:/POINTER=VALUE"), std::string::npos) << bad.err;
}

// With --frames N the session ends after frame N - 1: an action scripted for later would never
// happen and the scene would be saved unedited, so it is refused before the window opens (no
// display needed), and nothing is saved.
TEST(PyroViewAuthoring, ActionsPastTheLastFrameAreRefusedUpFront) {
  const fs::path dir = test::scratch_dir("view_authoring_past_frames");
  const fs::path scene = write_authoring_scene(dir);
  const fs::path saved = dir / "x.json";
  for (const Args& action : {Args{"--set-at", "99:/clouds/0/density=0.5"}, Args{"--undo-at", "3"},
                             Args{"--screenshot-at", "3:" + (dir / "late.png").string()},
                             Args{"--press-at", "5:B"}}) {
    Args args = {"view", scene.string(), "--frames", "3", "--save-as", saved.string()};
    args.insert(args.end(), action.begin(), action.end());
    const auto r = test::run_pyro_with("env -u DISPLAY", args);
    EXPECT_EQ(r.exit_code, 2) << action[0] << "\n" << r.err;
    EXPECT_NE(r.err.find("at " + action[0] + ": actions at frames the session reaches, 0 to 2 with --frames 3"),
              std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(saved));
  EXPECT_FALSE(fs::exists(dir / "late.png"));
}

}  // namespace
}  // namespace pyro
