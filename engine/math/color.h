#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pyro {

// Linear to sRGB transfer function (IEC 61966-2-1), input clamped to [0, 1].
inline float linear_to_srgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

inline float srgb_to_linear(float s) {
  s = std::clamp(s, 0.0f, 1.0f);
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

inline uint8_t to_byte(float v01) {
  return static_cast<uint8_t>(std::lround(std::clamp(v01, 0.0f, 1.0f) * 255.0f));
}

}  // namespace pyro
