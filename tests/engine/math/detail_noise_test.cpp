// The engine's detail-noise volume (Umenhoffer et al. 2006, section 3's detail video, made by
// the engine): values in [0, 1], deterministic from the seed, and periodic on every axis, so a
// GL_REPEAT texture has no seam: the step across the wrap is no larger than steps inside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/math/detail_noise.h"

namespace pyro {
namespace {

TEST(DetailNoise, RangeMeanAndDeterminism) {
  const DetailNoise a = make_detail_noise(32, 4, 3, 9);
  const DetailNoise b = make_detail_noise(32, 4, 3, 9);
  const DetailNoise c = make_detail_noise(32, 4, 3, 10);
  ASSERT_EQ(a.values.size(), 32u * 32u * 32u);
  EXPECT_EQ(a.values, b.values);
  EXPECT_NE(a.values, c.values);
  double sum = 0.0;
  for (float v : a.values) {
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
    sum += v;
  }
  // Lattice values are uniform on [0, 1): the mean of the interpolated sum is 1/2.
  EXPECT_NEAR(sum / a.values.size(), 0.5, 0.05);
}

TEST(DetailNoise, TilesWithoutASeamOnEveryAxis) {
  const DetailNoise n = make_detail_noise(32, 4, 3, 3);
  float inside = 0.0f, across = 0.0f;
  for (int i = 0; i < n.size; ++i)
    for (int j = 0; j < n.size; ++j) {
      for (int k = 0; k + 1 < n.size; ++k) {
        inside = std::max({inside, std::abs(detail_noise_at(n, k + 1, i, j) - detail_noise_at(n, k, i, j)),
                           std::abs(detail_noise_at(n, i, k + 1, j) - detail_noise_at(n, i, k, j)),
                           std::abs(detail_noise_at(n, i, j, k + 1) - detail_noise_at(n, i, j, k))});
      }
      const int last = n.size - 1;
      across = std::max({across, std::abs(detail_noise_at(n, 0, i, j) - detail_noise_at(n, last, i, j)),
                         std::abs(detail_noise_at(n, i, 0, j) - detail_noise_at(n, i, last, j)),
                         std::abs(detail_noise_at(n, i, j, 0) - detail_noise_at(n, i, j, last))});
    }
  EXPECT_GT(inside, 0.0f);
  EXPECT_LE(across, inside);
  // Wrapped lookups are the same texels.
  EXPECT_EQ(detail_noise_at(n, -1, 0, 0), detail_noise_at(n, n.size - 1, 0, 0));
}

// The shimmer's 2D slice (one fetch a pixel) must be the volume's trilinear sample: at a time on
// a layer's texel centre it is that layer; halfway between two layers, their mean; the second
// channel is the first's field half a period later, shifted by (size/2, size/4) texels.
TEST(DetailNoise, SliceIsTheVolumeInterpolatedInTime) {
  const DetailNoise n = make_detail_noise(16, 2, 2, 7);
  const int s = n.size;
  const double on_layer = (5 + 0.5) / s;  // texel centre of layer 5
  const std::vector<float> a = detail_noise_slice_rg(n, on_layer);
  const std::vector<float> b = detail_noise_slice_rg(n, on_layer + 0.5 / s);  // between 5 and 6
  for (int y = 0; y < s; ++y)
    for (int x = 0; x < s; ++x) {
      const size_t i = (static_cast<size_t>(y) * s + x) * 2;
      EXPECT_FLOAT_EQ(a[i], detail_noise_at(n, x, y, 5));
      EXPECT_NEAR(b[i], 0.5f * (detail_noise_at(n, x, y, 5) + detail_noise_at(n, x, y, 6)), 1e-6f);
      EXPECT_NEAR(a[i + 1], detail_noise_at(n, x + s / 2, y + s / 4, 5 + s / 2), 1e-6f);
    }
  // Periodic in time: one period later is the same slice.
  EXPECT_EQ(detail_noise_slice_rg(n, on_layer + 1.0), a);
}

}  // namespace
}  // namespace pyro
