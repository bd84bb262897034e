// PaletteBuilder and PaletteMapper: colours that fit the palette come back exactly, the mapping
// is the nearest palette colour (against a brute-force search), and a smooth image of many
// colours is reproduced within a bound that a fixed 3-3-2 palette cannot meet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "engine/io/palette_quantizer.h"

namespace pyro {
namespace {

// The index of the nearest colour by trying every one (lowest index on a tie).
uint8_t brute_force_nearest(const std::vector<PaletteColor>& palette, int r, int g, int b) {
  int best = 1 << 30;
  uint8_t nearest = 0;
  for (size_t i = 0; i < palette.size(); ++i) {
    const int dr = palette[i][0] - r, dg = palette[i][1] - g, db = palette[i][2] - b;
    const int d = dr * dr + dg * dg + db * db;
    if (d < best) {
      best = d;
      nearest = static_cast<uint8_t>(i);
    }
  }
  return nearest;
}

// Mean absolute difference per channel between `rgb` and its colours through the palette.
double quantized_mean_error(const std::vector<uint8_t>& rgb, PaletteMapper& mapper) {
  double sum = 0.0;
  for (size_t p = 0; p < rgb.size(); p += 3) {
    const PaletteColor& q = mapper.palette()[mapper.index_of(rgb[p], rgb[p + 1], rgb[p + 2])];
    for (int c = 0; c < 3; ++c) sum += std::abs(int(q[c]) - rgb[p + c]);
  }
  return sum / double(rgb.size());
}

TEST(PaletteQuantizer, AtMostAPaletteOfDistinctColoursIsKeptExactly) {
  // 200 distinct colours, each in its own histogram cell (multiples of 4), repeated unevenly.
  std::mt19937 rng(3);
  std::set<std::array<int, 3>> distinct;
  while (distinct.size() < 200)
    distinct.insert({int(rng() % 64) * 4, int(rng() % 64) * 4, int(rng() % 64) * 4});
  std::vector<uint8_t> rgb;
  int copies = 1;
  for (const auto& c : distinct) {
    for (int k = 0; k < copies; ++k) rgb.insert(rgb.end(), {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2])});
    copies = copies % 7 + 1;
  }
  PaletteBuilder builder;
  builder.add_pixels(rgb.data(), rgb.size() / 3);
  const std::vector<PaletteColor> palette = builder.palette(256);
  EXPECT_EQ(palette.size(), 200u) << "one colour per distinct cell";
  PaletteMapper mapper(palette);
  EXPECT_EQ(quantized_mean_error(rgb, mapper), 0.0);
}

TEST(PaletteQuantizer, MapsEveryColourToTheNearestPaletteColour) {
  std::mt19937 rng(11);
  std::vector<PaletteColor> palette(97);
  for (PaletteColor& p : palette) p = {uint8_t(rng()), uint8_t(rng()), uint8_t(rng())};
  palette[40] = palette[12];  // a duplicate: the lower index wins
  PaletteMapper mapper(palette);
  for (int i = 0; i < 200000; ++i) {
    const int r = int(rng() % 256), g = int(rng() % 256), b = int(rng() % 256);
    ASSERT_EQ(mapper.index_of(uint8_t(r), uint8_t(g), uint8_t(b)), brute_force_nearest(palette, r, g, b))
        << r << ", " << g << ", " << b;
  }
  EXPECT_EQ(mapper.index_of(palette[12][0], palette[12][1], palette[12][2]), 12);
}

// A sky-like gradient with a warm soft disc: tens of thousands of colours.
std::vector<uint8_t> gradient_image(int width, int height) {
  std::vector<uint8_t> rgb;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double cover = std::clamp(1.0 - std::hypot(x - 0.4 * width, y - 0.6 * height) / 40.0, 0.0, 1.0);
      const double sky[3] = {90.0 + 100.0 * y / height, 120.0 + 90.0 * y / height, 200.0 + 40.0 * x / width};
      const double fire[3] = {255.0, 170.0, 60.0};
      for (int c = 0; c < 3; ++c)
        rgb.push_back(uint8_t(std::lround(sky[c] * (1.0 - cover) + fire[c] * cover)));
    }
  return rgb;
}

TEST(PaletteQuantizer, SmoothImageIsKeptWithinTwoLevels) {
  const std::vector<uint8_t> rgb = gradient_image(160, 120);
  PaletteBuilder builder;
  builder.add_pixels(rgb.data(), rgb.size() / 3);
  PaletteMapper mapper(builder.palette(256));
  // A fixed 3-3-2 palette (levels 36.4 apart in red and green, 85 in blue) averages about 9,
  // 9 and 21 levels of error on such an image without dithering.
  std::vector<PaletteColor> fixed;
  for (int r = 0; r < 8; ++r)
    for (int g = 0; g < 8; ++g)
      for (int b = 0; b < 4; ++b)
        fixed.push_back({uint8_t(std::lround(r * 255.0 / 7)), uint8_t(std::lround(g * 255.0 / 7)),
                         uint8_t(std::lround(b * 255.0 / 3))});
  PaletteMapper fixed_mapper(fixed);
  const double made = quantized_mean_error(rgb, mapper), fixed_error = quantized_mean_error(rgb, fixed_mapper);
  std::printf("palette from the image: mean error %.3f levels; fixed 3-3-2: %.3f\n", made, fixed_error);
  EXPECT_LE(made, 2.0);
  EXPECT_GT(fixed_error, 4.0 * made);
}

}  // namespace
}  // namespace pyro
