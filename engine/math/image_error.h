#pragma once
// Image error measures used by every accuracy figure: RMSE over the RGB channels of linear
// images as a display shows them (negative values at 0, highlights above 1 rolled off as the
// final pass rolls them off: engine/math/highlight_rolloff.h), alpha ignored.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "engine/math/color.h"
#include "engine/math/highlight_rolloff.h"

namespace pyro {

// Linear RGBA floats, same size.
inline double rgba_rmse(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.size() % 4 != 0)
    throw std::invalid_argument("rgba_rmse: images differ in size");
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); i += 4) {
    const glm::vec3 d = roll_off_highlights({a[i], a[i + 1], a[i + 2]}) -
                        roll_off_highlights({b[i], b[i + 1], b[i + 2]});
    sum += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
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
