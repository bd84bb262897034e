#include "tools/bench/block_scoring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pyro {
namespace {

RgbImage filled_image(int width, int height, float value) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(size_t(3) * width * height, value);
  return image;
}

// Independent normal noise of standard deviation sigma on every value.
RgbImage with_noise(RgbImage image, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (float& v : image.rgb) v = float(v + normal(rng));
  return image;
}

TEST(BlockScoring, BlockMeansAreTheMeansOfWholeSquaresOfClampedValues) {
  RgbImage image = filled_image(5, 4, 0.0f);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y)[0] = float(x + 10 * y) / 100.0f;
  image.at(1, 1)[1] = 2.0f;   // clamped to 1
  image.at(0, 0)[2] = -1.0f;  // clamped to 0
  const RgbImage means = block_means(image, 2);
  ASSERT_EQ(means.width, 2);  // the fifth column is left out
  ASSERT_EQ(means.height, 2);
  // The mean of x + 10 y over x in {2i, 2i + 1}, y in {2j, 2j + 1}: 2i + 0.5 + 10 (2j + 0.5).
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(means.at(i, j)[0], (2 * i + 0.5 + 10 * (2 * j + 0.5)) / 100.0, 1e-7);
  EXPECT_NEAR(means.at(0, 0)[1], 0.25, 1e-7);
  EXPECT_NEAR(means.at(0, 0)[2], 0.0, 1e-7);
  EXPECT_THROW(block_means(image, 0), std::invalid_argument);
}

// Two renders of a flat grey, each with its own noise of sigma per value: the pixels differ by
// sigma sqrt(2), the 8 x 8 block means by sigma sqrt(2) / 8, and noise explains all of it.
TEST(BlockScoring, NoiseAloneShrinksByTheBlocksSideAndLeavesNoBias) {
  const double sigma = 0.02;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 1);
  const RgbImage b = with_noise(filled_image(256, 256, 0.5f), sigma, 2);
  EXPECT_NEAR(image_rmse(a, b), sigma * std::sqrt(2.0), 0.02 * sigma);
  const BlockScore s = block_score(a, b, 8, sigma / 8, sigma / 8);
  EXPECT_NEAR(s.rmse, sigma * std::sqrt(2.0) / 8, 0.1 * sigma / 8);
  EXPECT_NEAR(s.noise_rmse, sigma * std::sqrt(2.0) / 8, 1e-12);
  EXPECT_LT(s.bias_rmse, 0.001);
}

// A bias of 0.005 over half the frame, under noise four times larger: the pixels' RMSE moves by
// less than 1% of itself, the block means give the bias's RMS, 0.005 / sqrt(2).
TEST(BlockScoring, ABiasFarBelowTheNoiseShowsInTheBlockMeans) {
  const double sigma = 0.02, bias = 0.005;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 3);
  const RgbImage unbiased = with_noise(filled_image(256, 256, 0.5f), sigma, 4);
  RgbImage biased = unbiased;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 128; ++x)
      for (int c = 0; c < 3; ++c) biased.at(x, y)[c] += float(bias);
  EXPECT_LT(image_rmse(a, biased) - image_rmse(a, unbiased), 0.01 * image_rmse(a, unbiased));
  const BlockScore s = block_score(a, biased, 8, sigma / 8, sigma / 8);
  EXPECT_NEAR(s.bias_rmse, bias / std::sqrt(2.0), 0.15 * bias / std::sqrt(2.0));
  EXPECT_LT(block_score(a, unbiased, 8, sigma / 8, sigma / 8).bias_rmse, 0.3 * bias / std::sqrt(2.0));
}

}  // namespace
}  // namespace pyro
