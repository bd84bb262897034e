#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace pyro {

// Linear to sRGB transfer function (IEC 61966-2-1), input clamped to [0, 1].
inline float linear_to_srgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// The same transfer function as content/shaders/srgb_encode.glsl evaluates it where a pass writes
// sRGB bytes itself (GL_FRAMEBUFFER_SRGB off): the linear toe, then a degree-5 polynomial in
// sqrt(v), fitted here by iteratively reweighted least squares on [0.0031308, 1]. Its largest
// error is 3.4e-4, a twelfth of an 8-bit step, so every byte's decoded value encodes back to the
// byte. On llvmpipe it costs a fraction of GL's own conversion (figures in docs/explosions.md).
inline constexpr float kSrgbPolynomial[6] = {-0.0400807126f, 1.51741072f, -1.39971863f,
                                             2.02471918f,   -1.61693199f, 0.51493223f};
inline float linear_to_srgb_polynomial(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  if (v <= 0.0031308f) return 12.92f * v;
  const float t = std::sqrt(v);
  float p = kSrgbPolynomial[5];
  for (int k = 4; k >= 0; --k) p = p * t + kSrgbPolynomial[k];
  return p;
}

// The define content/shaders/srgb_encode.glsl takes its coefficients from ("SRGB_POLYNOMIAL
// c0, c1, ..., c5"): one set of numbers for the CPU and the shaders.
inline std::string srgb_polynomial_define() {
  std::string d = "SRGB_POLYNOMIAL ";
  char number[32];
  for (int k = 0; k < 6; ++k) {
    std::snprintf(number, sizeof number, "%s%.9g", k ? ", " : "", kSrgbPolynomial[k]);
    d += number;
  }
  return d;
}

inline float srgb_to_linear(float s) {
  s = std::clamp(s, 0.0f, 1.0f);
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

inline uint8_t to_byte(float v01) {
  return static_cast<uint8_t>(std::lround(std::clamp(v01, 0.0f, 1.0f) * 255.0f));
}

}  // namespace pyro
