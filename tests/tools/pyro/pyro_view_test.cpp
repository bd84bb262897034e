// pyro view end to end. Under a virtual X server (xvfb-run; skipped with a message when it is not
// installed — tools/install-deps.sh installs it): the window renders the explosion, the
// screenshot has the window's size and matches a headless `pyro render` of the same frame, the
// panels are drawn, and scripted edits of the scene file exercise the hot reload. Without a
// display: exit 3 and a message saying how to run it. Argument mistakes: exit 2 before any window.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/io/png_file.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"
#include "tests/support/xvfb.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

using test::have_xvfb_run;
using test::xvfb_launcher;

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

double mean(const PngImage& img, int x0, int y0, int x1, int y1) {
  double sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) sum += img.pixels[(size_t(y) * img.width + x) * 3 + c];
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

TEST(PyroView, RendersTheExplosionUnderXvfbAndMatchesTheHeadlessRender) {
  if (!have_xvfb_run()) GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("view");
  const std::string scene = test::scene_path("explosion.json");
  const auto r = test::run_pyro_with(
      xvfb_launcher(), {"view", scene, "--width", "160", "--height", "120", "--frames", "30",
                        "--no-overlay", "--screenshot", (dir / "shot.png").string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_EQ(j["frames"], 30);
  EXPECT_EQ(j["width"], 160);
  EXPECT_EQ(j["height"], 120);
  EXPECT_GT(j["fps"].get<double>(), 0.0);
  EXPECT_EQ(j["particles"], 263);
  const PngImage shot = read_png((dir / "shot.png").string());
  ASSERT_EQ(shot.width, 160);
  ASSERT_EQ(shot.height, 120);
  // Not the window's clear colour (0.05 → 13 in every channel) and not uniform.
  int differ = 0;
  for (size_t i = 0; i < shot.pixels.size(); ++i) differ += shot.pixels[i] != 13;
  EXPECT_GT(differ, int(shot.pixels.size()) * 9 / 10);

  // The 30th frame headless (frame_0029 is the state after 30 steps, as the viewer's 30th frame).
  const auto h = test::run_pyro({"render", scene, "--width", "160", "--height", "120", "--frames",
                                 "30", "--out", (dir / "headless").string()});
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const PngImage ref = read_png((dir / "headless" / "frame_0029.png").string());
  ASSERT_EQ(ref.pixels.size(), shot.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < ref.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(ref.pixels[i]) - int(shot.pixels[i])));
  EXPECT_LE(worst, 2) << "the window shows the runtime's output byte for byte (same driver)";

  // With the panels: the window holds the frame's part, at least as wide as the panels' column
  // (360), beside the column, and at least 240 high: 720 x 240. The frame is scaled to fit its
  // part, twice its size, centred (x 20 to 340), with nothing over it; the panels are drawn in
  // the column.
  const auto o = test::run_pyro_with(
      xvfb_launcher(), {"view", scene, "--width", "160", "--height", "120", "--frames", "30",
                        "--screenshot", (dir / "overlay.png").string(), "--json"});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const PngImage with_overlay = read_png((dir / "overlay.png").string());
  ASSERT_EQ(with_overlay.width, 720);
  ASSERT_EQ(with_overlay.height, 240);
  const auto view = test::last_json_line(o.out)["layout"]["view"];
  EXPECT_EQ(view, nlohmann::json({{"x", 20}, {"y", 0}, {"width", 320}, {"height", 240}}));
  EXPECT_NEAR(mean(with_overlay, 20 + 40, 60, 20 + 120, 120), mean(shot, 20, 30, 60, 60), 4.0);
  EXPECT_GT(std::abs(mean(with_overlay, 360, 0, 720, 30) - 13.0), 4.0) << "no panel header at the column's top";
}

TEST(PyroView, HotReloadReportsBrokenEditsAndAppliesTheGoodOne) {
  if (!have_xvfb_run()) GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("reload");
  const std::string original = read_text_file(test::scene_path("explosion.json"));
  const fs::path scene = dir / "scene.json";
  write_file(scene, original);
  // Three edits, each of a different length, so that every one changes the file's stamp.
  write_file(dir / "syntax.json", original.substr(0, original.rfind('}')));
  write_file(dir / "value.json", replaced(original, "\"fps\": 30", "\"fps\": -30"));
  write_file(dir / "good.json", replaced(original, "\"background\": [0.45, 0.55, 0.7]",
                                         "\"background\": [0.9, 0.1, 0.1]"));
  const auto r = test::run_pyro_with(
      xvfb_launcher(),
      {"view", scene.string(), "--width", "96", "--height", "72", "--frames", "24", "--no-overlay",
       "--replace-at", "4:" + (dir / "syntax.json").string(), "--replace-at",
       "10:" + (dir / "value.json").string(), "--replace-at", "16:" + (dir / "good.json").string(),
       "--screenshot", (dir / "shot.png").string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_EQ(j["frames"], 24);  // the broken edits did not stop the viewer
  const auto& reloads = j["reloads"];
  ASSERT_EQ(reloads.size(), 3u) << j.dump();
  EXPECT_EQ(reloads[0]["frame"], 4);
  EXPECT_FALSE(reloads[0]["ok"].get<bool>());
  const std::string syntax_error = reloads[0]["error"];
  EXPECT_NE(syntax_error.find(scene.string()), std::string::npos) << syntax_error;
  EXPECT_NE(syntax_error.find("line"), std::string::npos) << syntax_error;
  EXPECT_EQ(reloads[1]["frame"], 10);
  EXPECT_FALSE(reloads[1]["ok"].get<bool>());
  const std::string value_error = reloads[1]["error"];
  EXPECT_NE(value_error.find(scene.string()), std::string::npos) << value_error;
  EXPECT_NE(value_error.find("/output/fps"), std::string::npos) << value_error;
  EXPECT_EQ(reloads[2]["frame"], 16);
  EXPECT_TRUE(reloads[2]["ok"].get<bool>());
  EXPECT_NE(r.err.find("reload failed, keeping the last good scene"), std::string::npos) << r.err;
  // The good edit's red sky is on screen (the original sky is blue: 0.45, 0.55, 0.7 linear).
  const PngImage shot = read_png((dir / "shot.png").string());
  const size_t corner = 0;  // top left pixel: sky
  EXPECT_GT(shot.pixels[corner + 0], 200);
  EXPECT_LT(shot.pixels[corner + 1], 120);
  EXPECT_LT(shot.pixels[corner + 2], 120);
}

TEST(PyroView, KeysSwitchModesPauseStepAndQuit) {
  if (!have_xvfb_run()) GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("keys");
  const std::string scene = test::scene_path("explosion.json");
  // Key presses at given frames, through the same path as the keyboard's: anaglyph (4), viewpoint
  // billboards (B), layer scale 1/2 -> 1/4 (L), pause (Space) at frame 12, one step (N) at 15,
  // fly mode (Tab). Steps run at frames 0-11 and 15: the simulation is at frame 13.
  const auto r = test::run_pyro_with(
      xvfb_launcher(),
      {"view", scene, "--width", "96", "--height", "72", "--frames", "20", "--no-overlay",
       "--press-at", "3:4", "--press-at", "6:B", "--press-at", "9:L", "--press-at", "12:SPACE",
       "--press-at", "15:N", "--press-at", "16:TAB", "--screenshot", (dir / "shot.png").string(),
       "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = test::last_json_line(r.out);
  EXPECT_EQ(j["stereo"], "anaglyph");  // the names of --stereo and the scene file
  EXPECT_EQ(j["billboards"], "viewpoint");
  EXPECT_EQ(j["layer_scale"], 0.25);
  EXPECT_EQ(j["paused"], true);
  EXPECT_EQ(j["camera"], "fly");
  EXPECT_EQ(j["simulation_frame"], 13);
  EXPECT_EQ(j["frames"], 20);
  // The rebuilt runtimes carried the simulation on, and the paused frames redraw the last one:
  // the screenshot is frame 12 (13 steps) rendered headless with the same settings.
  const auto h = test::run_pyro({"render", scene, "--width", "96", "--height", "72", "--frames",
                                 "12:12", "--stereo", "anaglyph", "--billboards", "viewpoint",
                                 "--layer-scale", "0.25", "--out", (dir / "headless").string()});
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const PngImage ref = read_png((dir / "headless" / "frame_0012.png").string());
  const PngImage shot = read_png((dir / "shot.png").string());
  ASSERT_EQ(ref.pixels.size(), shot.pixels.size());
  int worst = 0;
  for (size_t i = 0; i < ref.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(ref.pixels[i]) - int(shot.pixels[i])));
  EXPECT_LE(worst, 2);

  // Esc quits at once, with exit status 0.
  const auto q = test::run_pyro_with(
      xvfb_launcher(), {"view", scene, "--width", "64", "--height", "48", "--frames", "1000",
                        "--press-at", "5:ESC", "--json"});
  ASSERT_EQ(q.exit_code, 0) << q.err;
  EXPECT_EQ(test::last_json_line(q.out)["frames"], 5);
}

TEST(PyroView, WithoutADisplayExitsThreeAndSaysHowToRunIt) {
  const fs::path dir = test::scratch_dir("nodisplay");
  const auto r = test::run_pyro_with(
      "env -u DISPLAY -u WAYLAND_DISPLAY",
      {"view", test::scene_path("explosion.json"), "--frames", "1", "--screenshot",
       (dir / "shot.png").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("DISPLAY is not set"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "shot.png"));
}

TEST(PyroView, ArgumentMistakesExitTwoBeforeAnyWindowOpens) {
  const fs::path dir = test::scratch_dir("args");
  const std::string scene = test::scene_path("explosion.json");
  // No display at all: a refusal must come before the window is asked for.
  const std::string no_display = "env -u DISPLAY -u WAYLAND_DISPLAY";
  auto r = test::run_pyro_with(no_display, {"view", scene, "--replace-at", "ten:x.json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--replace-at"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("FRAME:FILE"), std::string::npos) << r.err;
  r = test::run_pyro_with(no_display, {"view", scene, "--replace-at",
                                       "3:" + (dir / "missing.json").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
  r = test::run_pyro_with(no_display, {"view", scene, "--screenshot",
                                       (dir / "no_such_folder" / "shot.png").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--screenshot"), std::string::npos) << r.err;
  r = test::run_pyro_with(no_display, {"view", scene, "--expand", "sidebar"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--expand"), std::string::npos) << r.err;
  r = test::run_pyro_with(no_display, {"view", scene, "--press-at", "3:F5"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--press-at"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("F5"), std::string::npos) << r.err;
  write_file(dir / "broken.json", "{\"name\": ");
  r = test::run_pyro_with(no_display, {"view", (dir / "broken.json").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("broken.json"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pyro
