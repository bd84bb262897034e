// Preparing baked flame frames (Rose 2007, chapter 4; systems/flipbook_fire/flipbook_frame_fade.h):
// the window's closed form, its application in linear light, and the baked default flames: black
// borders in every frame, and a colour that runs from a bright, pale yellow base to red tips.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "systems/flipbook_fire/flipbook_folder.h"
#include "engine/math/color.h"
#include "systems/flipbook_fire/flipbook_frame_fade.h"
#include "tests/support/test_paths.h"

namespace pyro {
namespace {

namespace fs = std::filesystem;

float smoothstep01(float t) {
  t = std::fmin(std::fmax(t, 0.0f), 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

TEST(FlipbookFrameFade, WindowMatchesItsClosedForm) {
  const FrameFade f{0.25f, 0.2f, 0.1f};
  const int w = 40, h = 50;  // margins: 10 px each side, 10 px at the top, 5 px at the base
  EXPECT_EQ(frame_fade_weight(f, w, h, 0, 25), 0.0f);
  EXPECT_EQ(frame_fade_weight(f, w, h, w - 1, 25), 0.0f);
  EXPECT_EQ(frame_fade_weight(f, w, h, 20, 0), 0.0f);
  EXPECT_EQ(frame_fade_weight(f, w, h, 20, h - 1), 0.0f);
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, 20, 25), 1.0f);
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, 5, 25), 0.5f);            // smoothstep(1/2)
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, w - 1 - 5, 25), 0.5f);
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, 20, 5), 0.5f);
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, 20, h - 1 - 2), smoothstep01(0.4f));
  // A corner: the product of its two ramps.
  EXPECT_FLOAT_EQ(frame_fade_weight(f, w, h, 2, 3), smoothstep01(0.2f) * smoothstep01(0.3f));
  // Margins of 0 leave the borders alone.
  EXPECT_FLOAT_EQ(frame_fade_weight(FrameFade{0, 0, 0}, w, h, 0, 0), 1.0f);
}

TEST(FlipbookFrameFade, AppliesTheWindowInLinearLight) {
  const FrameFade f{0.25f, 0.2f, 0.1f};
  const int w = 40, h = 50;
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3, 200);
  apply_frame_fade(f, w, h, rgb);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int expected = to_byte(linear_to_srgb(frame_fade_weight(f, w, h, x, y) * srgb_to_linear(200 / 255.0f)));
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(rgb[(static_cast<size_t>(y) * w + x) * 3 + c], expected) << x << "," << y;
    }
  // Half weight in linear light is not half the byte: sRGB 200 -> 146 (0.578 / 2 = 0.289 linear), not 100.
  EXPECT_EQ(rgb[(25 * static_cast<size_t>(w) + 5) * 3], 146);
  std::vector<uint8_t> wrong(5);
  EXPECT_THROW(apply_frame_fade(f, w, h, wrong), std::invalid_argument);
}

// The default flame scene baked small: per row, the linear mean colour over all frames.
TEST(FlipbookFrameFade, BakedFlamesAreBlackAtTheBordersAndRedderTowardsTheTips) {
  const fs::path out = test::scratch_dir("baked_colour") / "flames";
  const test::CommandResult r =
      test::run_pyro({"bake-flipbook", test::scene_path("flipbook_fire.json"), "--out", out.string(),
                      "--frames", "8", "--width", "64", "--height", "96", "--loop-blend", "0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const FlipbookFrames frames = read_flipbook_folder(out.string());
  ASSERT_EQ(frames.rgba.size(), 8u);
  const int w = frames.width, h = frames.height;
  std::vector<std::array<double, 3>> row(static_cast<size_t>(h), {0.0, 0.0, 0.0});
  for (const std::vector<uint8_t>& px : frames.rgba) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint8_t* p = &px[(static_cast<size_t>(y) * w + x) * 4];
        if (x == 0 || x == w - 1 || y == 0) {
          ASSERT_LE(std::max({p[0], p[1], p[2]}), 1) << "border pixel " << x << "," << y;
        }
        for (int c = 0; c < 3; ++c) row[static_cast<size_t>(y)][static_cast<size_t>(c)] += srgb_to_linear(p[c] / 255.0f);
      }
  }
  // The flame's extent: rows whose mean luminance is at least 2% of the brightest row's.
  auto luma = [](const std::array<double, 3>& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
  double peak = 0.0;
  for (const auto& c : row) peak = std::max(peak, luma(c));
  ASSERT_GT(peak, 0.0);
  int first = -1, last = -1;  // top-most and bottom-most lit rows
  for (int y = 0; y < h; ++y)
    if (luma(row[static_cast<size_t>(y)]) >= 0.02 * peak) {
      if (first < 0) first = y;
      last = y;
    }
  ASSERT_GT(last - first, h / 3) << "a tall flame";
  // Thirds of the flame: the tips (top) and the base (bottom).
  const int third = (last - first + 1) / 3;
  std::array<double, 3> tips{}, base{};
  for (int y = first; y < first + third; ++y)
    for (int c = 0; c < 3; ++c) tips[static_cast<size_t>(c)] += row[static_cast<size_t>(y)][static_cast<size_t>(c)];
  for (int y = last - third + 1; y <= last; ++y)
    for (int c = 0; c < 3; ++c) base[static_cast<size_t>(c)] += row[static_cast<size_t>(y)][static_cast<size_t>(c)];
  const double base_rg = base[0] / base[1], tips_rg = tips[0] / tips[1];
  RecordProperty("base_r_over_g", std::to_string(base_rg));
  RecordProperty("tips_r_over_g", std::to_string(tips_rg));
  std::printf("flame rows %d..%d of %d; r/g base %.3f tips %.3f; luminance base/tips %.2f; base b/r %.3f\n",
              first, last, h, base_rg, tips_rg, luma(base) / luma(tips), base[2] / base[0]);
  // Black-body r/g (linear sRGB) is about 3.1 at 2250 K, the flame's hottest, 3.8 at 2000 K and
  // 6.9 at 1500 K (engine/math/blackbody.h).
  EXPECT_LT(base_rg, 3.5) << "an orange base";
  EXPECT_GT(tips_rg, 1.15 * base_rg) << "redder tips";
  EXPECT_GT(luma(base), 3.0 * luma(tips)) << "the base brightest, the tips fading out";
  // The r/g ratio of the row means rises (mostly) from the base to the tips: compare each
  // sixth of the flame with the next one up.
  const int sixth = std::max(1, (last - first + 1) / 6);
  double previous = 0.0;
  for (int k = 0; k < 6; ++k) {
    double r_sum = 0.0, g_sum = 0.0;
    for (int y = last - (k + 1) * sixth + 1; y <= last - k * sixth; ++y) {
      r_sum += row[static_cast<size_t>(y)][0];
      g_sum += row[static_cast<size_t>(y)][1];
    }
    const double rg = r_sum / g_sum;
    if (k > 0) {
      EXPECT_GT(rg, 0.95 * previous) << "sixth " << k << " from the base";
    }
    previous = rg;
  }
}

}  // namespace
}  // namespace pyro
