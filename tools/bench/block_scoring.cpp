#include "tools/bench/block_scoring.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pyro {

bool pixel_shows_medium(const RgbImage& image, int x, int y, const std::array<double, 3>& background) {
  const float* v = image.at(x, y);
  for (size_t c = 0; c < 3; ++c)
    if (std::abs(v[c] - background[c]) > 1e-6) return true;
  return false;
}

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

std::vector<bool> blocks_showing_medium(const RgbImage& image, int block, const std::array<double, 3>& background) {
  if (block < 1) throw std::invalid_argument("blocks_showing_medium: the block's side must be at least 1");
  const int columns = image.width / block, rows = image.height / block;
  std::vector<bool> shows(size_t(columns) * rows, false);
  for (int y = 0; y < rows * block; ++y)
    for (int x = 0; x < columns * block; ++x)
      if (pixel_shows_medium(image, x, y, background)) shows[size_t(y / block) * columns + x / block] = true;
  return shows;
}

double block_rmse(const RgbImage& a, const RgbImage& b, int block, const std::vector<bool>& chosen) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("block_rmse: sizes differ");
  const RgbImage ma = block_means(a, block), mb = block_means(b, block);
  if (chosen.size() != size_t(ma.width) * ma.height) throw std::invalid_argument("block_rmse: one choice per block");
  double sum = 0.0;
  size_t values = 0;
  for (size_t k = 0; k < chosen.size(); ++k) {
    if (!chosen[k]) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(ma.rgb[3 * k + size_t(c)]) - double(mb.rgb[3 * k + size_t(c)]);
      sum += d * d;
    }
    values += 3;
  }
  return values == 0 ? 0.0 : std::sqrt(sum / double(values));
}

BlockScore block_score(const RgbImage& a, const RgbImage& b, int block, const std::vector<bool>& chosen,
                       double a_block_noise, double b_block_noise) {
  BlockScore s;
  s.rmse = block_rmse(a, b, block, chosen);
  s.noise_rmse = std::hypot(a_block_noise, b_block_noise);
  s.bias_rmse = std::sqrt(std::max(s.rmse * s.rmse - s.noise_rmse * s.noise_rmse, 0.0));
  return s;
}

double independent_block_noise(double pixel_error, const RgbImage& image, int block, const std::vector<bool>& chosen) {
  const double pixels = double(image.width) * image.height;
  const double chosen_pixels = double(std::count(chosen.begin(), chosen.end(), true)) * block * block;
  return chosen_pixels == 0.0 ? 0.0 : pixel_error * std::sqrt(pixels / chosen_pixels) / block;
}

MeanDifference medium_mean_difference(const RgbImage& a, const RgbImage& b, const RgbImage& medium_of,
                                      const std::array<double, 3>& background) {
  if (a.width != b.width || a.height != b.height || a.width != medium_of.width || a.height != medium_of.height)
    throw std::invalid_argument("medium_mean_difference: sizes differ");
  double sum = 0.0, sum2 = 0.0;
  MeanDifference m;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!pixel_shows_medium(medium_of, x, y, background)) continue;
      double d = 0.0;
      for (int c = 0; c < 3; ++c) d += std::clamp(double(a.at(x, y)[c]), 0.0, 1.0) - std::clamp(double(b.at(x, y)[c]), 0.0, 1.0);
      d /= 3.0;
      sum += d;
      sum2 += d * d;
      ++m.pixels;
    }
  if (m.pixels == 0) return m;
  const double n = double(m.pixels);
  m.mean = sum / n;
  const double variance = m.pixels > 1 ? std::max(sum2 - n * m.mean * m.mean, 0.0) / (n - 1.0) : 0.0;
  m.standard_error = std::sqrt(variance / n);
  return m;
}

}  // namespace pyro
