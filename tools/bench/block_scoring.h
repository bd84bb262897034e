// Two noisy renders of one frame scored by the means of square blocks of pixels: independent
// pixel noise shrinks by the block's side in a block mean, a bias that covers the block does not,
// so the block means see a bias that the pixels' RMSE hides under the noise.
#pragma once

#include "systems/runtime/reference/rgb_image.h"

namespace pyro {

// The mean of each whole `block` x `block` square (from the top-left corner; a partial row or
// column of pixels at the right or bottom is left out), each value clamped to [0, 1] first as
// image_rmse does: an image of width / block by height / block pixels.
RgbImage block_means(const RgbImage& image, int block);

// image_rmse of the two images' block means.
double block_rmse(const RgbImage& a, const RgbImage& b, int block);

// What the block means say of a difference between two renders, each with its noise:
//   rmse:       the block means' RMSE (block_rmse);
//   noise_rmse: the RMSE noise alone would give them, sqrt(first_noise^2 + second_noise^2), each
//               the RMS standard error of a block mean;
//   bias_rmse:  sqrt(max(rmse^2 - noise_rmse^2, 0)), the RMS of what the noise does not explain.
struct BlockScore {
  double rmse = 0.0, noise_rmse = 0.0, bias_rmse = 0.0;
};
BlockScore block_score(const RgbImage& a, const RgbImage& b, int block, double a_block_noise, double b_block_noise);

}  // namespace pyro
