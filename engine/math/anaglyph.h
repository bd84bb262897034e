#pragma once
// Anaglyph stereo as linear maps: out = L * left + R * right, clamped to [0, 1], applied to
// LINEAR RGB. Dubois derives his least-squares matrices in a linear colour space (CIE XYZ of
// the display primaries seen through the filters' transmission spectra), so they are only
// meaningful on linear values: the output is encoded to sRGB afterwards, like any frame.
// The colour and half-colour anaglyphs are written as matrices too, so one composition pass
// (content/shaders/compose.frag) serves every mode; the shader receives these matrices
// as uniforms.
#include <array>
#include <string>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace pyro {

enum class AnaglyphKind { dubois, color, half_color };

struct AnaglyphMatrices {
  glm::mat3 left{0.0f};
  glm::mat3 right{0.0f};
};

// Row-major numbers as published, converted to glm's column-major layout.
AnaglyphMatrices anaglyph_matrices(AnaglyphKind kind);

glm::vec3 apply_anaglyph(const AnaglyphMatrices& m, const glm::vec3& left, const glm::vec3& right);

}  // namespace pyro
