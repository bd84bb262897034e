// RMSE of images against closed forms: a uniform offset, alpha ignored, display clamping, sRGB
// decoding.
#include <gtest/gtest.h>

#include "engine/math/image_error.h"

namespace pyro {
namespace {

TEST(ImageError, UniformOffsetGivesThatOffset) {
  std::vector<float> a(4 * 10, 0.25f), b(4 * 10, 0.25f);
  for (size_t i = 0; i < b.size(); ++i) b[i] += (i % 4 == 3) ? 0.9f : 0.1f;  // alpha differs too
  EXPECT_NEAR(rgba_rmse(a, b), 0.1, 1e-7);
}

TEST(ImageError, ValuesAreClampedToWhatADisplayShows) {
  const std::vector<float> a = {2.0f, -1.0f, 0.5f, 1.0f}, b = {1.0f, 0.0f, 0.5f, 0.0f};
  EXPECT_EQ(rgba_rmse(a, b), 0.0);
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
