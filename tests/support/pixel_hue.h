#pragma once
// HSV of a colour (hue in degrees [0, 360), saturation and value in [0, 1]), and the census of an
// 8-bit image's yellow-green pixels: hue in [58°, 100°], saturation > 0.25 and value > 0.15 among
// its coloured pixels (saturation > 0.25, value > 0.15). Black-body emission never makes those
// hues: its chromaticities run from red through orange to white (hue below about 45°).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace pyro::test {

struct Hsv {
  float hue = 0.0f, saturation = 0.0f, value = 0.0f;
};

inline Hsv hsv_of(glm::vec3 c) {
  const float mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z}), d = mx - mn;
  Hsv h;
  h.value = mx;
  h.saturation = mx > 0.0f ? d / mx : 0.0f;
  if (d <= 0.0f) return h;
  float sector = mx == c.x ? std::fmod((c.y - c.z) / d + 6.0f, 6.0f)
                 : mx == c.y ? (c.z - c.x) / d + 2.0f
                             : (c.x - c.y) / d + 4.0f;
  h.hue = 60.0f * sector;
  return h;
}

struct HueCensus {
  size_t coloured = 0;      // saturation > 0.25 and value > 0.15
  size_t yellow_green = 0;  // of those, hue in [58°, 100°]
  double fraction() const { return coloured ? double(yellow_green) / double(coloured) : 0.0; }
};

// `pixels`: 8-bit sRGB, `channels` per pixel (3 or 4), the bytes as stored (as a viewer sees them).
inline HueCensus hue_census(const std::vector<uint8_t>& pixels, int channels) {
  HueCensus census;
  for (size_t i = 0; i + 2 < pixels.size(); i += size_t(channels)) {
    const Hsv h = hsv_of(glm::vec3(pixels[i], pixels[i + 1], pixels[i + 2]) / 255.0f);
    if (h.saturation <= 0.25f || h.value <= 0.15f) continue;
    ++census.coloured;
    census.yellow_green += h.hue >= 58.0f && h.hue <= 100.0f;
  }
  return census;
}

}  // namespace pyro::test
