#pragma once
// Image error measures used by every accuracy figure: RMSE over the RGB channels of linear
// images, values clamped to [0, 1] (what a display can show), alpha ignored.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "engine/math/color.h"

namespace pyro {

// Linear RGBA floats, same size.
inline double rgba_rmse(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.size() % 4 != 0)
    throw std::invalid_argument("rgba_rmse: images differ in size");
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = std::clamp(a[i], 0.0f, 1.0f) - std::clamp(b[i], 0.0f, 1.0f);
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / (a.size() / 4 * 3));
}

// sRGB-encoded RGBA bytes (as shown), decoded to linear before comparing.
inline double srgb8_rmse(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size() || a.size() % 4 != 0)
    throw std::invalid_argument("srgb8_rmse: images differ in size");
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = srgb_to_linear(a[i] / 255.0f) - srgb_to_linear(b[i] / 255.0f);
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / (a.size() / 4 * 3));
}

}  // namespace pyro
