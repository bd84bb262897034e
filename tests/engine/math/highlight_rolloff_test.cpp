// The display's highlight roll-off (engine/math/highlight_rolloff.h): unchanged within range,
// the largest channel 1 beyond it, the HSV hue kept exactly, every channel non-decreasing with
// exposure, and continuous where it starts. Per-channel clipping, which it replaces, fails the
// hue check on the first orange it sees.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "engine/math/highlight_rolloff.h"
#include "tests/support/pixel_hue.h"

namespace pyro {
namespace {

// Hue distance in degrees, around the circle.
float hue_distance(float a, float b) {
  const float d = std::abs(a - b);
  return std::min(d, 360.0f - d);
}

TEST(HighlightRolloff, ColoursWithinRangeAreUnchanged) {
  for (const glm::vec3 c : {glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(0.9f, 0.4f, 0.05f),
                            glm::vec3(1.0f, 0.0f, 0.5f)})
    EXPECT_EQ(roll_off_highlights(c), c);
  EXPECT_EQ(roll_off_highlights(glm::vec3(-0.2f, 0.5f, 0.3f)), glm::vec3(0.0f, 0.5f, 0.3f));
}

TEST(HighlightRolloff, KeepsTheHueAndBringsTheLargestChannelToOne) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> channel(0.0f, 1.0f), exposure(1.01f, 60.0f);
  for (int i = 0; i < 2000; ++i) {
    glm::vec3 c(channel(rng), channel(rng), channel(rng));
    const float m = std::max({c.x, c.y, c.z});
    if (m - std::min({c.x, c.y, c.z}) < 0.05f) continue;  // near grey: hue undefined
    c *= exposure(rng) / m;
    const glm::vec3 out = roll_off_highlights(c);
    EXPECT_NEAR(std::max({out.x, out.y, out.z}), 1.0f, 1e-5f);
    EXPECT_GE(std::min({out.x, out.y, out.z}), 0.0f);
    EXPECT_LT(hue_distance(test::hsv_of(out).hue, test::hsv_of(c).hue), 0.05f) << i;
  }
}

TEST(HighlightRolloff, PerChannelClippingWouldTurnABlackBodyOrangeYellow) {
  // The black-body orange of about 2000 K, three times over the display's range.
  const glm::vec3 orange = 3.0f * glm::vec3(1.0f, 0.42f, 0.1f);
  const float clipped = test::hsv_of(glm::min(orange, glm::vec3(1.0f))).hue;
  const float rolled = test::hsv_of(roll_off_highlights(orange)).hue;
  EXPECT_GT(clipped, 58.0f);  // the yellow-green band of the hue census
  EXPECT_NEAR(rolled, test::hsv_of(orange).hue, 0.05f);
  EXPECT_LT(rolled, 45.0f);
}

TEST(HighlightRolloff, BrighterNeverDarkensAndTheStartIsContinuous) {
  const glm::vec3 hue(1.0f, 0.42f, 0.1f);
  glm::vec3 last = roll_off_highlights(0.5f * hue);
  for (float k = 0.5f; k < 40.0f; k *= 1.01f) {
    const glm::vec3 out = roll_off_highlights(k * hue);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(out, last - 1e-6f))) << k;
    last = out;
  }
  const glm::vec3 below = roll_off_highlights(0.9999f * hue), above = roll_off_highlights(1.0001f * hue);
  EXPECT_LT(glm::length(above - below), 1e-3f);
  // Far past the range, the colour turns white.
  EXPECT_GT(std::min({roll_off_highlights(1000.0f * hue).z, 1.0f}), 0.99f);
}

}  // namespace
}  // namespace pyro
