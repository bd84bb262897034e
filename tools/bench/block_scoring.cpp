#include "tools/bench/block_scoring.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pyro {

RgbImage block_means(const RgbImage& image, int block) {
  if (block < 1) throw std::invalid_argument("block_means: the block's side must be at least 1");
  RgbImage means;
  means.width = image.width / block;
  means.height = image.height / block;
  means.rgb.assign(size_t(3) * means.width * means.height, 0.0f);
  const double per_block = 1.0 / (double(block) * block);
  for (int by = 0; by < means.height; ++by)
    for (int bx = 0; bx < means.width; ++bx) {
      double sum[3] = {0.0, 0.0, 0.0};
      for (int y = by * block; y < (by + 1) * block; ++y)
        for (int x = bx * block; x < (bx + 1) * block; ++x)
          for (int c = 0; c < 3; ++c) sum[c] += std::clamp(double(image.at(x, y)[c]), 0.0, 1.0);
      for (int c = 0; c < 3; ++c) means.at(bx, by)[c] = float(sum[c] * per_block);
    }
  return means;
}

double block_rmse(const RgbImage& a, const RgbImage& b, int block) {
  return image_rmse(block_means(a, block), block_means(b, block));
}

BlockScore block_score(const RgbImage& a, const RgbImage& b, int block, double a_block_noise, double b_block_noise) {
  BlockScore s;
  s.rmse = block_rmse(a, b, block);
  s.noise_rmse = std::hypot(a_block_noise, b_block_noise);
  s.bias_rmse = std::sqrt(std::max(s.rmse * s.rmse - s.noise_rmse * s.noise_rmse, 0.0));
  return s;
}

}  // namespace pyro
