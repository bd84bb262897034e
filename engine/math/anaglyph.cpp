#include "engine/math/anaglyph.h"

#include <glm/common.hpp>

namespace pyro {

namespace {

glm::mat3 from_rows(const std::array<float, 9>& r) {
  // glm::mat3 is indexed [column][row].
  glm::mat3 m;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = r[static_cast<size_t>(row * 3 + col)];
  return m;
}

}  // namespace

AnaglyphMatrices anaglyph_matrices(AnaglyphKind kind) {
  AnaglyphMatrices m;
  switch (kind) {
    case AnaglyphKind::dubois:
      // E. Dubois, "A projection method to generate anaglyph stereo images", ICASSP 2001; the
      // red-cyan matrices he published for typical CRT primaries and red/cyan filters
      // (the same ones Johnson & McAllister cite, ref. 9, for their figure 17).
      m.left = from_rows({0.456f, 0.500f, 0.176f,
                          -0.040f, -0.038f, -0.016f,
                          -0.015f, -0.021f, -0.005f});
      m.right = from_rows({-0.043f, -0.088f, -0.002f,
                           0.378f, 0.734f, -0.018f,
                           -0.072f, -0.113f, 1.226f});
      break;
    case AnaglyphKind::color:
      // Red from the left eye, green and blue from the right.
      m.left = from_rows({1, 0, 0, 0, 0, 0, 0, 0, 0});
      m.right = from_rows({0, 0, 0, 0, 1, 0, 0, 0, 1});
      break;
    case AnaglyphKind::half_color:
      // Red from the left eye's luminance (Rec. 709 weights, for linear RGB), green and blue
      // from the right: less retinal rivalry on saturated reds.
      m.left = from_rows({0.2126f, 0.7152f, 0.0722f, 0, 0, 0, 0, 0, 0});
      m.right = from_rows({0, 0, 0, 0, 1, 0, 0, 0, 1});
      break;
  }
  return m;
}

glm::vec3 apply_anaglyph(const AnaglyphMatrices& m, const glm::vec3& left, const glm::vec3& right) {
  return glm::clamp(m.left * left + m.right * right, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace pyro
