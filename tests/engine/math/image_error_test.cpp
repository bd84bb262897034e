// RMSE of images against closed forms: a uniform offset, alpha ignored, values as a display shows
// them, sRGB decoding.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/math/image_error.h"

namespace pyro {
namespace {

TEST(ImageError, UniformOffsetGivesThatOffset) {
  std::vector<float> a(4 * 10, 0.25f), b(4 * 10, 0.25f);
  for (size_t i = 0; i < b.size(); ++i) b[i] += (i % 4 == 3) ? 0.9f : 0.1f;  // alpha differs too
  EXPECT_NEAR(rgba_rmse(a, b), 0.1, 1e-7);
}

TEST(ImageError, ValuesAreComparedAsADisplayShowsThem) {
  // Negative at 0; above 1, c / m² + 1 − 1/m with m the largest channel (2 here): the display's
  // roll-off, which keeps the hue.
  const std::vector<float> a = {2.0f, -1.0f, 0.5f, 1.0f}, b = {1.0f, 0.5f, 0.625f, 0.0f};
  EXPECT_NEAR(rgba_rmse(a, b), 0.0, 1e-7);
  const std::vector<float> grey = {3.0f, 3.0f, 3.0f, 1.0f}, white = {1.0f, 1.0f, 1.0f, 1.0f};
  EXPECT_NEAR(rgba_rmse(grey, white), 0.0, 1e-7);
  // Per-channel clipping would call {2, -1, 0.5} and {1, 0, 0.5} the same colour.
  EXPECT_NEAR(rgba_rmse(a, {1.0f, 0.0f, 0.5f, 0.0f}), std::sqrt((0.25 + 0.125 * 0.125) / 3.0), 1e-7);
}

TEST(ImageError, SrgbBytesAreComparedInLinearLight) {
  const std::vector<uint8_t> black = {0, 0, 0, 255}, white = {255, 255, 255, 0};
  EXPECT_NEAR(srgb8_rmse(black, white), 1.0, 1e-7);
  const std::vector<uint8_t> mid = {188, 188, 188, 255};  // sRGB 188/255 is about 0.5 linear
  EXPECT_NEAR(srgb8_rmse(black, mid), srgb_to_linear(188 / 255.0f), 1e-7);
  EXPECT_THROW(srgb8_rmse(black, std::vector<uint8_t>(8, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace pyro
