#include "engine/math/flame_flicker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pyro {
namespace {

TEST(PuffingFrequency, FollowsCetegenAndAhmedsFit) {
  EXPECT_DOUBLE_EQ(puffing_frequency(1.0), 1.5);
  EXPECT_NEAR(puffing_frequency(0.25), 3.0, 1e-12);
  EXPECT_NEAR(puffing_frequency(100.0), 0.15, 1e-12);
}

// Over a long run the scale has mean 1 and rms deviation equal to the amplitude; its power sits
// at the puffing frequency (the DFT there against twice and three times it); no amplitude is
// steady, and the seed moves the phases.
TEST(FlameFlicker, HasMeanOneRmsAmplitudeAndItsPowerAtThePuffingFrequency) {
  const FlameFlicker f{0.2, 1.9, 7u};
  const double dt = 1.0 / 240.0;
  const int n = 240 * 600;
  double mean = 0.0, square = 0.0;
  for (int k = 0; k < n; ++k) mean += flame_flicker(f, k * dt);
  mean /= n;
  for (int k = 0; k < n; ++k) square += std::pow(flame_flicker(f, k * dt) - mean, 2);
  EXPECT_NEAR(mean, 1.0, 2e-3);
  EXPECT_NEAR(std::sqrt(square / n), 0.2, 2e-3);
  const auto power_at = [&](double hz) {
    double re = 0.0, im = 0.0;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * hz * k * dt, v = flame_flicker(f, k * dt) - mean;
      re += v * std::cos(a);
      im += v * std::sin(a);
    }
    return (re * re + im * im) / (double(n) * n);
  };
  EXPECT_GT(power_at(1.9), 50.0 * power_at(3.8));
  EXPECT_GT(power_at(1.9), 50.0 * power_at(5.7));
  EXPECT_EQ(flame_flicker({0.0, 1.9, 7u}, 0.37), 1.0);
  EXPECT_NE(flame_flicker(f, 0.37), flame_flicker({0.2, 1.9, 8u}, 0.37));
  EXPECT_EQ(flame_flicker(f, 0.37), flame_flicker(f, 0.37));
}

}  // namespace
}  // namespace pyro
