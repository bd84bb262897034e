// pyro view's layout: the window it opens, the frame's place beside the panel column, and the
// panels stacked in the column, against sizes worked out by hand.
#include "tools/viewer/panel_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pyro {
namespace {

// Collapsed panels' height and the gap between panels, as the viewer draws them at scale 1.
constexpr float kHeader = 27.0f;
constexpr float kGap = 2.0f;

bool rects_overlap(const PanelRect& a, const PanelRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
         b.y < a.y + a.height && a.width > 0 && a.height > 0 && b.width > 0 && b.height > 0;
}

bool rect_inside(const PanelRect& r, const PanelRect& outer) {
  return r.x >= outer.x && r.y >= outer.y && r.x + r.width <= outer.x + outer.width &&
         r.y + r.height <= outer.y + outer.height && r.width >= 0 && r.height >= 0;
}

void expect_stacked_inside(const std::vector<PanelRect>& rects, const PanelRect& column) {
  for (size_t i = 0; i < rects.size(); ++i) {
    EXPECT_TRUE(rect_inside(rects[i], column)) << i;
    for (size_t j = 0; j < i; ++j) EXPECT_FALSE(rects_overlap(rects[i], rects[j])) << i << " " << j;
  }
}

TEST(PanelLayout, TheWindowHoldsTheFrameBesideTheColumn) {
  EXPECT_EQ(panel_column_width(1.0f), 360.0f);
  EXPECT_EQ(panel_column_width(1.5f), 540.0f);
  EXPECT_EQ(viewer_window_size(400, 300, 360), (WindowSize{760, 300}));
  EXPECT_EQ(viewer_window_size(480, 270, 360), (WindowSize{840, 270}));
  EXPECT_EQ(viewer_window_size(1280, 720, 360), (WindowSize{1640, 720}));
  // A frame narrower than the column, or too short for the column's headers, gets room around it.
  EXPECT_EQ(viewer_window_size(320, 400, 360), (WindowSize{720, 400}));
  EXPECT_EQ(viewer_window_size(128, 192, 360), (WindowSize{720, 240}));
  // Without panels, the frame's own size.
  EXPECT_EQ(viewer_window_size(160, 120, 0), (WindowSize{160, 120}));
}

TEST(PanelLayout, TheColumnTakesTheRightEdgeAndAtMostHalfTheWindow) {
  WindowSplit s = split_window(840, 270, 360);
  EXPECT_EQ(s.view, (PanelRect{0, 0, 480, 270}));
  EXPECT_EQ(s.column, (PanelRect{480, 0, 360, 270}));
  // Narrower than twice the column: half the window, in whole pixels.
  s = split_window(680, 400, 360);
  EXPECT_EQ(s.column, (PanelRect{340, 0, 340, 400}));
  s = split_window(501, 300, 360);
  EXPECT_EQ(s.column, (PanelRect{251, 0, 250, 300}));
  EXPECT_EQ(s.view, (PanelRect{0, 0, 251, 300}));
  s = split_window(160, 120, 0);
  EXPECT_EQ(s.view, (PanelRect{0, 0, 160, 120}));
  EXPECT_EQ(s.column.width, 0.0f);
}

TEST(PanelLayout, TheFrameFitsItsAreaCentredInWholePixels) {
  EXPECT_EQ(fit_frame({0, 0, 320, 400}, 320, 400), (PanelRect{0, 0, 320, 400}));
  EXPECT_EQ(fit_frame({0, 0, 480, 300}, 480, 270), (PanelRect{0, 15, 480, 270}));
  // 128x192 in 360x240: scale min(360/128, 240/192) = 1.25, so 160x240, 100 pixels each side.
  EXPECT_EQ(fit_frame({0, 0, 360, 240}, 128, 192), (PanelRect{100, 0, 160, 240}));
  // Half size: 640x360 in 320x400 is 320x180, 110 pixels above and below.
  EXPECT_EQ(fit_frame({10, 0, 320, 400}, 640, 360), (PanelRect{10, 110, 320, 180}));
}

TEST(PanelLayout, CollapsedPanelsAreHeadersUnderTheExpandedOnes) {
  const PanelRect column{320, 0, 360, 400};
  const std::vector<PanelRect> r = stack_panels(
      column,
      {{kHeader, 100, true}, {kHeader, 520, false}, {kHeader, 300, false}, {kHeader, 140, false}},
      kGap);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], (PanelRect{320, 0, 360, 100}));
  EXPECT_EQ(r[1], (PanelRect{320, 102, 360, kHeader}));
  EXPECT_EQ(r[2], (PanelRect{320, 131, 360, kHeader}));
  EXPECT_EQ(r[3], (PanelRect{320, 160, 360, kHeader}));
}

TEST(PanelLayout, ExpandedPanelsShareWhatTheHeadersLeaveFairly) {
  const std::vector<ColumnPanel> all = {
      {kHeader, 100, true}, {kHeader, 520, true}, {kHeader, 300, true}, {kHeader, 140, true}};
  // Headers and gaps: 4 * 27 + 3 * 2 = 114. In a 500-pixel column that leaves 386 for bodies
  // that want 73, 493, 273 and 113. From the smallest: 73 (less than 386 / 4), then
  // min(113, 313 / 3) = 104, min(273, 209 / 2) = 104, and the 105 left.
  std::vector<PanelRect> r = stack_panels({0, 0, 360, 500}, all, kGap);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], (PanelRect{0, 0, 360, 100}));
  EXPECT_EQ(r[1], (PanelRect{0, 102, 360, kHeader + 105}));
  EXPECT_EQ(r[2], (PanelRect{0, 236, 360, kHeader + 104}));
  EXPECT_EQ(r[3], (PanelRect{0, 369, 360, kHeader + 104}));
  expect_stacked_inside(r, {0, 0, 360, 500});
  // In 270 pixels, 156 left: 39 each, every body wanting more than that.
  r = stack_panels({0, 0, 360, 270}, all, kGap);
  for (const PanelRect& p : r) EXPECT_EQ(p.height, kHeader + 39);
  expect_stacked_inside(r, {0, 0, 360, 270});
  // What fits is given in full: the stereo panel alone.
  const std::vector<PanelRect> one = stack_panels(
      {0, 0, 360, 270},
      {{kHeader, 100, false}, {kHeader, 520, false}, {kHeader, 300, false}, {kHeader, 140, true}},
      kGap);
  EXPECT_EQ(one[3], (PanelRect{0, 87, 360, 140}));
}

TEST(PanelLayout, AColumnTooShortForTheHeadersClipsThemInsideIt) {
  const PanelRect column{100, 10, 200, 60};
  const std::vector<PanelRect> r = stack_panels(
      column,
      {{kHeader, 100, true}, {kHeader, 520, true}, {kHeader, 300, false}, {kHeader, 140, false}},
      kGap);
  expect_stacked_inside(r, column);
  EXPECT_EQ(r[0].height, kHeader);
  EXPECT_EQ(r[2].height, 60 - 2 * (kHeader + kGap));
  EXPECT_EQ(r[3].height, 0.0f);
}

// The viewer's default at any window size: the status expanded up to a quarter of the column,
// the other three collapsed, cover at most a third of the window, beside the frame.
TEST(PanelLayout, TheDefaultPanelsCoverAThirdOfAnyWindowAtMost) {
  for (float w = 240; w <= 2400; w += 37) {
    for (float h = 240; h <= 1400; h += 29) {
      const WindowSplit s = split_window(w, h, 360);
      const float status = std::min(kHeader + 9 * 17.0f, h / 4);
      const std::vector<PanelRect> r = stack_panels(s.column,
                                                    {{kHeader, status, true},
                                                     {kHeader, 520, false},
                                                     {kHeader, 300, false},
                                                     {kHeader, 140, false}},
                                                    kGap);
      float area = 0;
      for (const PanelRect& p : r) {
        EXPECT_FALSE(rects_overlap(p, s.view));
        area += p.width * p.height;
      }
      expect_stacked_inside(r, s.column);
      EXPECT_LE(area, w * h / 3) << w << "x" << h;
    }
  }
}

}  // namespace
}  // namespace pyro
