#include "systems/flipbook_fire/flipbook_emission.h"

#include <array>

#include "engine/math/color.h"

namespace pyro {

namespace {

// A six-way flipbook gives off its emissive value (lightmap B's alpha, linear) times its opacity
// (lightmap A's alpha), grey: smoke baked with no emission gives off nothing.
FlipbookEmission six_way_emission(const FlipbookFrames& frames) {
  FlipbookEmission out;
  for (size_t f = 0; f < frames.rgba.size(); ++f) {
    const std::vector<uint8_t>& a = frames.rgba[f];
    const std::vector<uint8_t>& b = frames.six_way_b.at(f);
    double sum = 0.0;
    const size_t texels = a.size() / 4;
    for (size_t t = 0; t < texels; ++t) sum += (a[4 * t + 3] / 255.0) * (b[4 * t + 3] / 255.0);
    out.frame_radiance.push_back(glm::vec3(texels ? static_cast<float>(sum / double(texels)) : 0.0f));
  }
  return out;
}

}  // namespace

FlipbookEmission flipbook_emission(const FlipbookFrames& frames, FlipbookBlend blend) {
  if (frames.six_way()) return six_way_emission(frames);
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
