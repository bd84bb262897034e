#pragma once
// What a display shows of linear radiance that exceeds its range. Clipping each channel at 1
// shifts hue: an orange black-body core, (3, 1.6, 0.4) say, clips to (1, 1, 0.4), a saturated
// yellow that no black-body makes, and dimmed or overlapped it reads olive. Instead, a colour
// whose largest channel m exceeds 1 is scaled to m = 1 and mixed toward white by 1 - 1/m:
//   out = c / m² + (1 − 1/m)        (m = max(r, g, b) > 1; out = c below)
// A positive scale plus an equal offset on every channel keeps the HSV hue exactly; the largest
// channel is 1, saturation falls as 1/m (an overexposed core turns white, as on film), every
// channel grows with exposure, and the map is continuous at m = 1. content/shaders/
// highlight_rolloff.glsl is the same function for the final pass.
#include <algorithm>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace pyro {

inline glm::vec3 roll_off_highlights(glm::vec3 c) {
  c = glm::max(c, glm::vec3(0.0f));
  const float m = std::max({c.x, c.y, c.z});
  if (m <= 1.0f) return c;
  return c / (m * m) + glm::vec3(1.0f - 1.0f / m);
}

}  // namespace pyro
