#include "systems/flipbook_fire/flipbook_emission.h"

#include <array>

#include "engine/math/color.h"

namespace pyro {

FlipbookEmission flipbook_emission(const FlipbookFrames& frames, FlipbookBlend blend) {
  std::array<float, 256> linear{};
  for (int v = 0; v < 256; ++v) linear[size_t(v)] = srgb_to_linear(float(v) / 255.0f);
  FlipbookEmission out;
  for (const std::vector<uint8_t>& rgba : frames.rgba) {
    glm::dvec3 sum(0.0);
    const size_t texels = rgba.size() / 4;
    for (size_t t = 0; t < texels; ++t) {
      const double a = blend == FlipbookBlend::linear_alpha ? rgba[4 * t + 3] / 255.0 : 1.0;
      for (int c = 0; c < 3; ++c) sum[c] += a * linear[rgba[4 * t + size_t(c)]];
    }
    out.frame_radiance.push_back(texels ? glm::vec3(sum / double(texels)) : glm::vec3(0.0f));
  }
  return out;
}

}  // namespace pyro
