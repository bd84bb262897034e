#include "tools/bench/block_scoring.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// Independent normal noise of standard deviation sigma on every value of the square [lo, hi)^2.
RgbImage with_noise(RgbImage image, double sigma, unsigned seed, int lo = 0, int hi = 1 << 30) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, sigma);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (x >= lo && x < hi && y >= lo && y < hi)
        for (int c = 0; c < 3; ++c) image.at(x, y)[c] = float(image.at(x, y)[c] + normal(rng));
  return image;
}

std::vector<bool> every_block(const RgbImage& image, int block) {
  return std::vector<bool>(size_t(image.width / block) * (image.height / block), true);
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

TEST(BlockScoring, TheMediumsBlocksAreThoseWhereTheImageLeavesTheBackground) {
  RgbImage a = filled_image(16, 8, 0.25f);
  a.at(9, 2)[1] = 0.3f;           // block (2, 0)
  a.at(3, 7)[2] = 0.25f + 1e-3f;  // block (0, 1)
  a.at(14, 5)[0] = 0.25f + 1e-7f;  // within 1e-6: still background
  const std::vector<bool> shows = blocks_showing_medium(a, 4, {0.25, 0.25, 0.25});
  EXPECT_EQ(shows, (std::vector<bool>{false, false, true, false, true, false, false, false}));
}

// Two renders of a flat grey, each with its own noise of sigma per value: the pixels differ by
// sigma sqrt(2), the 8 x 8 block means by sigma sqrt(2) / 8, and noise explains all of it.
TEST(BlockScoring, NoiseAloneShrinksByTheBlocksSideAndLeavesNoBias) {
  const double sigma = 0.02;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 1);
  const RgbImage b = with_noise(filled_image(256, 256, 0.5f), sigma, 2);
  EXPECT_NEAR(image_rmse(a, b), sigma * std::sqrt(2.0), 0.02 * sigma);
  const BlockScore s = block_score(a, b, 8, every_block(a, 8), sigma / 8, sigma / 8);
  EXPECT_NEAR(s.rmse, sigma * std::sqrt(2.0) / 8, 0.1 * sigma / 8);
  EXPECT_NEAR(s.noise_rmse, sigma * std::sqrt(2.0) / 8, 1e-12);
  EXPECT_LT(s.bias_rmse, 0.001);
}

// Noise only inside a square of a quarter of the frame: over the blocks that show it, a block
// mean's error is the frame's RMS pixel error sqrt(4) / 8, as the two renders' difference says.
TEST(BlockScoring, TheNoiseOfTheMediumsBlocksFollowsFromTheFramesPixelError) {
  const double sigma = 0.02;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 5, 64, 192);
  const RgbImage b = with_noise(filled_image(256, 256, 0.5f), sigma, 6, 64, 192);
  const std::vector<bool> shows = blocks_showing_medium(a, 8, {0.5, 0.5, 0.5});
  EXPECT_EQ(std::count(shows.begin(), shows.end(), true), 16 * 16);
  const double pixel_error = sigma / 2;  // RMS over the frame: sigma over a quarter of it
  EXPECT_NEAR(independent_block_noise(pixel_error, a, 8, shows), sigma / 8, 1e-12);
  EXPECT_NEAR(block_rmse(a, b, 8, shows) / std::sqrt(2.0), sigma / 8, 0.1 * sigma / 8);
}

// A bias of 0.005 over the medium, a quarter of the frame, under noise four times larger: the
// pixels' RMSE moves by about 1% of itself; over the medium's blocks the bias comes out whole.
TEST(BlockScoring, ABiasFarBelowTheNoiseShowsInTheMediumsBlockMeans) {
  const double sigma = 0.02, bias = 0.005;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 3, 64, 192);
  const RgbImage unbiased = with_noise(filled_image(256, 256, 0.5f), sigma, 4, 64, 192);
  RgbImage biased = unbiased;
  for (int y = 64; y < 192; ++y)
    for (int x = 64; x < 192; ++x)
      for (int c = 0; c < 3; ++c) biased.at(x, y)[c] += float(bias);
  EXPECT_LT(image_rmse(a, biased) - image_rmse(a, unbiased), 0.02 * image_rmse(a, unbiased));
  const std::vector<bool> shows = blocks_showing_medium(a, 8, {0.5, 0.5, 0.5});
  const double noise = independent_block_noise(sigma / 2, a, 8, shows);
  EXPECT_NEAR(block_score(a, biased, 8, shows, noise, noise).bias_rmse, bias, 0.15 * bias);
  EXPECT_LT(block_score(a, unbiased, 8, shows, noise, noise).bias_rmse, 0.3 * bias);
}

// Each channel's independent noise sigma in both renders: a pixel's channel-averaged difference
// has standard deviation sigma sqrt(2 / 3), the mean over the medium's n pixels sigma sqrt(2 / 3) / sqrt(n);
// a bias of 0.005, a quarter of sigma, stands more than ten standard errors from 0.
TEST(BlockScoring, TheMediumsMeanDifferenceSeesABiasOfOneSign) {
  const double sigma = 0.02, bias = 0.005;
  const RgbImage a = with_noise(filled_image(256, 256, 0.5f), sigma, 7, 64, 192);
  const RgbImage b = with_noise(filled_image(256, 256, 0.5f), sigma, 8, 64, 192);
  const MeanDifference unbiased = medium_mean_difference(a, b, a, {0.5, 0.5, 0.5});
  EXPECT_EQ(unbiased.pixels, 128u * 128u);
  const double standard_error = sigma * std::sqrt(2.0 / 3.0) / 128.0;
  EXPECT_NEAR(unbiased.standard_error, standard_error, 0.05 * standard_error);
  EXPECT_LT(std::abs(unbiased.mean), 4.0 * standard_error);
  RgbImage biased = a;
  for (int y = 64; y < 192; ++y)
    for (int x = 64; x < 192; ++x)
      for (int c = 0; c < 3; ++c) biased.at(x, y)[c] += float(bias);
  const MeanDifference seen = medium_mean_difference(biased, b, a, {0.5, 0.5, 0.5});
  EXPECT_NEAR(seen.mean, bias, 4.0 * standard_error);
  EXPECT_GT(seen.mean, 10.0 * seen.standard_error);
}

}  // namespace
}  // namespace pyro
