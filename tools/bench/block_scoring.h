// Two noisy renders of one frame scored by the means of square blocks of pixels: independent
// pixel noise shrinks by the block's side in a block mean, a bias that covers the block does not,
// so the block means see a bias that the pixels' RMSE hides under the noise. Blocks of empty
// background (no noise, no bias) would only dilute it: the scores are over the blocks where the
// medium shows.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

// Whether pixel (x, y) of `image` shows the medium: differs from `background` by more than 1e-6
// in a channel.
bool pixel_shows_medium(const RgbImage& image, int x, int y, const std::array<double, 3>& background);

// The mean of each whole `block` x `block` square (from the top-left corner; a partial row or
// column of pixels at the right or bottom is left out), each value clamped to [0, 1] first as
// image_rmse does: an image of width / block by height / block pixels.
RgbImage block_means(const RgbImage& image, int block);

// For each block of block_means, row by row: whether a pixel of `image` in it shows the medium.
std::vector<bool> blocks_showing_medium(const RgbImage& image, int block, const std::array<double, 3>& background);

// sqrt(mean over the chosen blocks and their channels of (mean of a - mean of b)^2); 0 with none.
double block_rmse(const RgbImage& a, const RgbImage& b, int block, const std::vector<bool>& chosen);

// What the block means say of a difference between two renders, each with its noise, over the
// chosen blocks:
//   rmse:       block_rmse;
//   noise_rmse: the RMSE noise alone would give them, sqrt(first_noise^2 + second_noise^2), each
//               the RMS standard error of a chosen block's mean;
//   bias_rmse:  sqrt(max(rmse^2 - noise_rmse^2, 0)), the RMS of what the noise does not explain.
struct BlockScore {
  double rmse = 0.0, noise_rmse = 0.0, bias_rmse = 0.0;
};
BlockScore block_score(const RgbImage& a, const RgbImage& b, int block, const std::vector<bool>& chosen,
                       double a_block_noise, double b_block_noise);

// The RMS standard error of a chosen block's mean for an image whose pixels are independent and
// whose RMS standard error over all its pixels is `pixel_error`, all of the noise in the chosen
// blocks: pixel_error sqrt(pixels / chosen pixels) / block.
double independent_block_noise(double pixel_error, const RgbImage& image, int block, const std::vector<bool>& chosen);

// The mean over the pixels where `medium_of` shows the medium of the difference a - b, each pixel's values clamped to [0, 1] and its channels
// averaged, and the standard error of that mean: the pixels' differences' standard deviation over
// sqrt(their count). A bias of one sign over the medium shows as a mean several standard errors
// from 0 even where it is far below the pixels' noise.
struct MeanDifference {
  double mean = 0.0, standard_error = 0.0;
  std::size_t pixels = 0;
};
MeanDifference medium_mean_difference(const RgbImage& a, const RgbImage& b, const RgbImage& medium_of,
                                      const std::array<double, 3>& background);

}  // namespace pyro
