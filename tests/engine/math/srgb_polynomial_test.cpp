// engine/math/color.h: the polynomial sRGB encoding the opaque and compose passes use
// (content/shaders/srgb_encode.glsl) against the exact transfer function.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/math/color.h"

namespace pyro {
namespace {

TEST(SrgbPolynomial, WithinATwelfthOfAStepOfTheExactCurve) {
  double worst = 0.0;
  for (int i = 0; i <= 1000000; ++i) {
    const float v = static_cast<float>(i) / 1000000.0f;
    worst = std::max(worst, static_cast<double>(std::abs(linear_to_srgb_polynomial(v) - linear_to_srgb(v))));
  }
  EXPECT_LT(worst, 3.5e-4);  // 1/255 = 3.9e-3: a step
  EXPECT_GT(worst, 1e-5);    // an approximation, not the exact curve by another name
  EXPECT_EQ(linear_to_srgb_polynomial(-1.0f), 0.0f);
  EXPECT_NEAR(linear_to_srgb_polynomial(2.0f), 1.0f, 3.5e-4);
}

TEST(SrgbPolynomial, EveryByteEncodesBackToItself) {
  // A scene byte decoded by the texture unit and encoded again by a pass that leaves it
  // unchanged must come out as the same byte.
  for (int b = 0; b < 256; ++b) {
    const float linear = srgb_to_linear(b / 255.0f);
    EXPECT_EQ(to_byte(linear_to_srgb_polynomial(linear)), b) << b;
  }
}

}  // namespace
}  // namespace pyro
