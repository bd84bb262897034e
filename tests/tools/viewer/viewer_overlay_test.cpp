// pyro view's overlay text: wrapping and what the lines say.
#include "tools/viewer/viewer_overlay.h"

#include <gtest/gtest.h>

#include <sstream>

#include "tools/viewer/viewer_keys.h"

namespace pyro {
namespace {

std::string words_of(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& l : lines) {
    std::istringstream in(l);
    std::string w;
    while (in >> w) all += w + " ";
  }
  return all;
}

TEST(ViewerOverlay, WrapKeepsEveryWordAndNoLineIsTooLong) {
  const std::string text =
      "scene.json: at /emitters/0/dynamics/curves/size: expected an array of [t, value] pairs "
      "with t increasing in [0, 1], found [[0.5, 1], [0.25, 2]]";
  for (int columns : {1, 7, 20, 33, 200}) {
    const auto lines = wrap_text(text, columns);
    for (const std::string& l : lines) EXPECT_LE(int(l.size()), columns) << l;
    if (columns >= 34) {
      // The longest word (34 characters) fits whole: the same words in the same order.
      std::istringstream in(text);
      std::string expected, w;
      while (in >> w) expected += w + " ";
      EXPECT_EQ(words_of(lines), expected) << columns;
    }
  }
  EXPECT_EQ(wrap_text("abcdefghij", 4), (std::vector<std::string>{"abcd", "efgh", "ij"}));
  EXPECT_EQ(wrap_text("one two three", 7), (std::vector<std::string>{"one two", "three"}));
  EXPECT_EQ(wrap_text("a\nb", 10), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(wrap_text("", 10), (std::vector<std::string>{""}));
}

OverlayInfo sample() {
  OverlayInfo i;
  i.fps = 42.5;
  i.frame_ms = 23.5;
  i.frame = 120;
  i.particles = 263;
  i.system_ms = {{"sorting", 0.25}, {"composite", 12.0}};
  i.stereo = "ANAGLYPH";
  i.billboards = "VIEWPLANE";
  i.layer_scale = "1/2";
  i.camera = "ORBIT";
  return i;
}

TEST(ViewerOverlay, LinesShowRateCountsModesAndSystemTimes) {
  const auto lines = overlay_lines(sample(), 80);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "42.5 FPS  23.5 MS  FRAME 120  263 PARTICLES");
  EXPECT_EQ(lines[1].text, "ANAGLYPH  VIEWPLANE  LAYER 1/2  ORBIT");
  EXPECT_EQ(lines[2].text, "MS: sorting 0.25  composite 12.00");
  for (const OverlayLine& l : lines) EXPECT_FALSE(l.error);
  OverlayInfo paused = sample();
  paused.paused = true;
  EXPECT_NE(overlay_lines(paused, 80)[0].text.find("PAUSED"), std::string::npos);
}

TEST(ViewerOverlay, TheHeaderCarriesRateFrameAndPause) {
  OverlayInfo i = sample();
  EXPECT_EQ(overlay_header(i), "Status  42.5 fps  frame 120");
  i.paused = true;
  EXPECT_EQ(overlay_header(i), "Status  42.5 fps  frame 120  PAUSED");
}

TEST(ViewerOverlay, AReloadErrorIsShownWrappedInTheErrorColour) {
  OverlayInfo i = sample();
  i.error = "/tmp/scene.json: at /output/fps: expected a number > 0, found -30";
  const int columns = 24;
  const auto lines = overlay_lines(i, columns);
  std::vector<std::string> error_lines;
  for (const OverlayLine& l : lines) {
    EXPECT_LE(int(l.text.size()), columns);
    if (l.error) error_lines.push_back(l.text);
  }
  ASSERT_GE(error_lines.size(), 3u);
  EXPECT_EQ(words_of(error_lines),
            "RELOAD FAILED, KEEPING THE LAST GOOD SCENE: /tmp/scene.json: at /output/fps: "
            "expected a number > 0, found -30 ");
}

TEST(ViewerOverlay, HelpListsEveryKey) {
  OverlayInfo i = sample();
  i.help = true;
  const auto lines = overlay_lines(i, 100);
  const auto keys = key_help_lines();
  size_t found = 0;
  for (const OverlayLine& l : lines)
    for (const std::string& k : keys) found += l.text == k;
  EXPECT_EQ(found, keys.size());
}

}  // namespace
}  // namespace pyro
