#include "systems/flipbook_fire/flipbook_frame_fade.h"

#include <algorithm>
#include <stdexcept>

#include "engine/math/color.h"

namespace pyro {

namespace {

// smoothstep of d / margin; a margin of 0 (or less than a pixel) leaves the border alone.
float ramp(float d, float margin) {
  if (!(margin > 0.0f)) return 1.0f;
  const float t = std::clamp(d / margin, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float frame_fade_weight(const FrameFade& fade, int width, int height, int x, int y) {
  const float side = fade.side * static_cast<float>(width);
  const float top = fade.top * static_cast<float>(height);
  const float base = fade.base * static_cast<float>(height);
  return ramp(static_cast<float>(x), side) * ramp(static_cast<float>(width - 1 - x), side) *
         ramp(static_cast<float>(y), top) * ramp(static_cast<float>(height - 1 - y), base);
}

void apply_frame_fade(const FrameFade& fade, int width, int height, std::vector<uint8_t>& rgb) {
  if (rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3)
    throw std::invalid_argument("apply_frame_fade: expected width x height RGB8 pixels");
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float w = frame_fade_weight(fade, width, height, x, y);
      if (w >= 1.0f) continue;
      uint8_t* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c) p[c] = to_byte(linear_to_srgb(w * srgb_to_linear(p[c] / 255.0f)));
    }
}

}  // namespace pyro
