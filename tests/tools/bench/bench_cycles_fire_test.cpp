// The fire's scores against Cycles (tools/bench/bench_cycles_fire.h, score_fire_against_cycles)
// on images made here: the same light scores 0; light of another black body's colour at the same
// luminances differs by exactly the two temperatures' xy apart, with no luminance error; a pixel
// below the emitting fraction is not scored however wrong its colour.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "engine/math/blackbody.h"
#include "tools/bench/bench_cycles_fire.h"

namespace pyro {
namespace {

// A width x 1 image of the black body's colour at temperature `kelvin`, pixel i at luminance
// weights[i] (relative), the colour's own luminance normalised out.
RgbImage glowing_row(double kelvin, const std::vector<double>& weights) {
  const BlackbodyColor c = blackbody_color(kelvin);
  const double y = 0.2126 * c.rgb.x + 0.7152 * c.rgb.y + 0.0722 * c.rgb.z;
  RgbImage image;
  image.width = int(weights.size());
  image.height = 1;
  for (double w : weights)
    for (int k = 0; k < 3; ++k) image.rgb.push_back(float(w * c.rgb[k] / y));
  return image;
}

TEST(BenchCyclesFire, TheSameLightScoresZero) {
  const RgbImage a = glowing_row(1800.0, {1.0, 0.5, 0.25, 0.0});
  const nlohmann::json s = score_fire_against_cycles(a, a, 0.05);
  EXPECT_EQ(s["emitting_pixels"], 3);
  EXPECT_NEAR(s["chromaticity_difference"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(s["pixel_chromaticity_difference_p90"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(s["relative_luminance_rmse"].get<double>(), 0.0, 1e-6);
}

TEST(BenchCyclesFire, AnotherBlackBodysColourDiffersByItsChromaticity) {
  // The last pixel is below 5 % of Cycles' brightest: its colour (blue-white) does not count.
  std::vector<double> weights = {1.0, 0.6, 0.3, 0.02};
  RgbImage ours = glowing_row(2000.0, weights);
  const RgbImage cycles = glowing_row(2300.0, weights);
  const BlackbodyColor blue = blackbody_color(9000.0);
  for (int k = 0; k < 3; ++k) ours.rgb[9 + k] = float(0.02 * blue.rgb[k]);
  const nlohmann::json s = score_fire_against_cycles(ours, cycles, 0.05);
  const double apart = glm::length(blackbody_color(2000.0).xy - blackbody_color(2300.0).xy);
  EXPECT_EQ(s["emitting_pixels"], 3);
  EXPECT_NEAR(s["chromaticity_difference"].get<double>(), apart, 1e-6);
  EXPECT_NEAR(s["pixel_chromaticity_difference_median"].get<double>(), apart, 1e-6);
  EXPECT_NEAR(s["relative_luminance_rmse"].get<double>(), 0.0, 1e-6);
  EXPECT_GT(apart, 0.02);
}

}  // namespace
}  // namespace pyro
