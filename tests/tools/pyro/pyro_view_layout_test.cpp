// Where pyro view puts its panels, at the templates' own small frame sizes (320x400, 480x270),
// under a virtual X server (skipped with a message when xvfb-run is not installed). Each session
// pauses at once, saves the window with its panels, hides them (O) and saves it again: the two
// images differ exactly where a panel is drawn. By default the panels cover at most a third of
// the window, lie inside it and inside the rectangles the viewer reports (--json "layout"), do not
// overlap one another, and leave the scene's frame whole at its own size; with every panel
// expanded (--expand) they still lie apart, inside the window and off the frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/content_path.h"
#include "engine/io/png_file.h"
#include "tests/support/json_output.h"
#include "tests/support/test_paths.h"
#include "tests/support/xvfb.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

// One session's two screenshots (panels shown, then hidden) and its summary.
struct PanelShots {
  PngImage shown, hidden;
  nlohmann::json summary;
};

PanelShots panel_shots(const std::string& scene, const fs::path& dir,
                       const std::vector<std::string>& more = {}) {
  // Space at frame 0 pauses before the first step: every frame shows the same image.
  std::vector<std::string> args = {"view", scene, "--frames", "8", "--press-at", "0:SPACE",
                                   "--screenshot-at", "5:" + (dir / "shown.png").string(),
                                   "--press-at", "6:O", "--screenshot-at",
                                   "7:" + (dir / "hidden.png").string(), "--json"};
  args.insert(args.end(), more.begin(), more.end());
  const auto r = test::run_pyro_with(test::xvfb_launcher(), args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  PanelShots shots;
  if (r.exit_code != 0) return shots;
  shots.shown = read_png((dir / "shown.png").string());
  shots.hidden = read_png((dir / "hidden.png").string());
  shots.summary = test::last_json_line(r.out);
  return shots;
}

bool pixel_differs(const PngImage& a, const PngImage& b, int x, int y) {
  const size_t at = (size_t(y) * size_t(a.width) + size_t(x)) * 3;
  return a.pixels[at] != b.pixels[at] || a.pixels[at + 1] != b.pixels[at + 1] ||
         a.pixels[at + 2] != b.pixels[at + 2];
}

// The share of the window's pixels a panel changed.
double panel_pixel_share(const PanelShots& s) {
  size_t changed = 0;
  for (int y = 0; y < s.shown.height; ++y)
    for (int x = 0; x < s.shown.width; ++x) changed += pixel_differs(s.shown, s.hidden, x, y);
  return double(changed) / (double(s.shown.width) * double(s.shown.height));
}

struct LayoutRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

LayoutRect layout_rect(const nlohmann::json& j) {
  const double x = j.at("x"), y = j.at("y"), w = j.at("width"), h = j.at("height");
  return {x, y, x + w, y + h};
}

double overlap_area(const LayoutRect& a, const LayoutRect& b) {
  const double w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
  const double h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0.0;
}

bool inside_some(const std::vector<LayoutRect>& rects, int x, int y) {
  for (const LayoutRect& r : rects)
    if (x + 0.5 >= r.x0 && x + 0.5 <= r.x1 && y + 0.5 >= r.y0 && y + 0.5 <= r.y1) return true;
  return false;
}

// The reported rectangles: inside the window, apart from each other and from the frame, at most
// `max_share` of the window, and every pixel a panel changed inside one of them.
void expect_reported_layout_holds(const PanelShots& s, int frame_width, int frame_height,
                                  double max_share) {
  ASSERT_TRUE(s.summary.contains("layout")) << "the summary reports no panel layout";
  const nlohmann::json& layout = s.summary["layout"];
  const LayoutRect window{0, 0, double(s.shown.width), double(s.shown.height)};
  const LayoutRect view = layout_rect(layout.at("view"));
  EXPECT_EQ(view.x1 - view.x0, frame_width) << "the frame is shown at its own size";
  EXPECT_EQ(view.y1 - view.y0, frame_height);
  std::vector<LayoutRect> panels;
  double area = 0;
  for (const nlohmann::json& p : layout.at("panels")) {
    const LayoutRect r = layout_rect(p);
    EXPECT_DOUBLE_EQ(overlap_area(r, window), (r.x1 - r.x0) * (r.y1 - r.y0)) << p.dump();
    EXPECT_EQ(overlap_area(r, view), 0.0) << p.dump();
    for (const LayoutRect& other : panels) EXPECT_EQ(overlap_area(r, other), 0.0) << p.dump();
    panels.push_back(r);
    area += (r.x1 - r.x0) * (r.y1 - r.y0);
  }
  EXPECT_EQ(panels.size(), 4u) << layout.dump();
  EXPECT_LE(area, window.x1 * window.y1 * max_share) << layout.dump();
  size_t stray = 0;
  for (int y = 0; y < s.shown.height; ++y)
    for (int x = 0; x < s.shown.width; ++x)
      stray += pixel_differs(s.shown, s.hidden, x, y) && !inside_some(panels, x, y);
  EXPECT_EQ(stray, 0u) << "pixels drawn by a panel outside the rectangles reported";
}

void expect_panels_leave_the_scene(const std::string& scene, int frame_width, int frame_height) {
  if (!test::have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("panels_" + std::to_string(frame_width));
  const PanelShots s = panel_shots(scene, dir);
  ASSERT_FALSE(s.shown.pixels.empty());
  ASSERT_EQ(s.shown.width, s.hidden.width);
  ASSERT_EQ(s.shown.height, s.hidden.height);
  ASSERT_GE(s.shown.width, frame_width);
  ASSERT_GE(s.shown.height, frame_height);
  const double share = panel_pixel_share(s);
  std::printf("%dx%d frame, %dx%d window: panels drew %.1f%% of it\n", frame_width, frame_height,
              s.shown.width, s.shown.height, 100.0 * share);
  EXPECT_LE(share, 1.0 / 3.0) << "the panels changed " << 100.0 * share << "% of the window";
  expect_reported_layout_holds(s, frame_width, frame_height, 1.0 / 3.0);
}

TEST(PyroViewLayout, PanelsCoverAThirdAtMostOfTheWindowOfATallSmallFrame) {
  expect_panels_leave_the_scene(content_path("templates/smoke.json"), 320, 400);
}

TEST(PyroViewLayout, PanelsCoverAThirdAtMostOfTheWindowOfAWideSmallFrame) {
  expect_panels_leave_the_scene(content_path("templates/fog.json"), 480, 270);
}

// Every panel expanded (--expand) in the lower of the two windows: they share the column, still
// inside the window, apart and off the frame; each is more than its header.
TEST(PyroViewLayout, ExpandedPanelsShareTheColumnWithoutOverlapping) {
  if (!test::have_xvfb_run())
    GTEST_SKIP() << "xvfb-run is not installed (tools/install-deps.sh installs xvfb)";
  const fs::path dir = test::scratch_dir("panels_expanded");
  const PanelShots s = panel_shots(content_path("templates/fog.json"), dir,
                                   {"--expand", "status", "--expand", "inspector", "--expand",
                                    "profiler", "--expand", "stereo"});
  ASSERT_FALSE(s.shown.pixels.empty());
  expect_reported_layout_holds(s, 480, 270, 1.0);
  for (const nlohmann::json& p : s.summary["layout"]["panels"]) {
    EXPECT_TRUE(p["expanded"].get<bool>()) << p.dump();
    EXPECT_GT(p["height"].get<double>(), 40.0) << p.dump();
  }
}

}  // namespace
}  // namespace pyro
