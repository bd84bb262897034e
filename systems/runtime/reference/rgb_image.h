#pragma once
// A linear RGB float image (top row first) and the root-mean-square difference of two of them.
#include <cmath>
#include <stdexcept>
#include <vector>

namespace pyro {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 floats per pixel
  float* at(int x, int y) { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  const float* at(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
};

// sqrt(mean over pixels and channels of (a - b)^2), each value clamped to [0, 1] first.
inline double image_rmse(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("image_rmse: sizes differ");
  if (a.rgb.empty()) return 0.0;
  const auto clamp01 = [](float v) { return v < 0.0f ? 0.0 : v > 1.0f ? 1.0 : double(v); };
  double s = 0.0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = clamp01(a.rgb[i]) - clamp01(b.rgb[i]);
    s += d * d;
  }
  return std::sqrt(s / double(a.rgb.size()));
}

}  // namespace pyro
