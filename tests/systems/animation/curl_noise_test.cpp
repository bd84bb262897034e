// Curl-noise turbulence: divergence-free (numerically), and the noise gradient is exact.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "systems/animation/curl_noise.h"

namespace pyro {
namespace {

TEST(CurlNoise, DivergenceIsZero) {
  // Central differences of the field: ∂u/∂x + ∂v/∂y + ∂w/∂z, relative to the field's typical
  // derivative size. O(h²) truncation and float rounding remain.
  const float h = 1e-2f;
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 p(0.37f * i - 11.0f, std::sin(0.7f * i) * 5.0f, std::cos(1.3f * i) * 4.0f + 0.5f);
    const auto d = [&](int axis) {
      glm::vec3 e(0.0f);
      e[axis] = h;
      return (curl_noise(p + e, 9)[axis] - curl_noise(p - e, 9)[axis]) / (2.0f * h);
    };
    const double div = d(0) + d(1) + d(2);
    worst = std::max(worst, std::abs(div));
    scale = std::max({scale, std::abs(static_cast<double>(d(0))), std::abs(static_cast<double>(d(1)))});
  }
  EXPECT_GT(scale, 0.1);        // the field does vary
  EXPECT_LT(worst, 2e-3 * scale);  // and its divergence is ~0
}

TEST(CurlNoise, AnalyticGradientMatchesFiniteDifferences) {
  const double h = 1e-3;
  for (int i = 0; i < 50; ++i) {
    const glm::vec3 p(0.91f * i - 20.0f, 0.33f * i, -0.57f * i + 3.0f);
    glm::vec3 g;
    value_noise(p, 3, &g);
    for (int a = 0; a < 3; ++a) {
      glm::vec3 e(0.0f);
      e[a] = static_cast<float>(h);
      const double fd = (value_noise(p + e, 3) - value_noise(p - e, 3)) / (2.0 * h);
      EXPECT_NEAR(g[a], fd, 2e-2) << i << " " << a;
    }
  }
}

TEST(CurlNoise, DeterministicAndSeeded) {
  const glm::vec3 p(1.2f, -3.4f, 5.6f);
  EXPECT_EQ(curl_noise(p, 4), curl_noise(p, 4));
  EXPECT_NE(curl_noise(p, 4), curl_noise(p, 5));
}

}  // namespace
}  // namespace pyro
