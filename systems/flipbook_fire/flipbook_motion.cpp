#include "systems/flipbook_fire/flipbook_motion.h"

#include <algorithm>
#include <cmath>

namespace pyro {

namespace {

uint8_t encode_component(float m, float strength) {
  const float c = std::clamp(0.5f + 0.5f * m / strength, 0.0f, 1.0f);
  return static_cast<uint8_t>(std::lround(c * 255.0f));
}

float decode_component(uint8_t c, float strength) {
  return (2.0f * static_cast<float>(c) / 255.0f - 1.0f) * strength;
}

}  // namespace

float motion_strength(const std::vector<MotionField>& fields) {
  float largest = 0.0f;
  for (const MotionField& f : fields)
    for (float m : f.uv) largest = std::max(largest, std::abs(m));
  return std::max(largest * (1.0f + 1.0f / 127.0f), 1e-4f);
}

std::vector<uint8_t> encode_motion(const MotionField& field, float strength) {
  const size_t pixels = static_cast<size_t>(field.width) * field.height;
  std::vector<uint8_t> rgba(pixels * 4);
  for (size_t i = 0; i < pixels; ++i) {
    rgba[i * 4 + 0] = encode_component(field.uv[i * 2], strength);
    rgba[i * 4 + 1] = encode_component(-field.uv[i * 2 + 1], strength);  // v up in the file
    rgba[i * 4 + 2] = 0;
    rgba[i * 4 + 3] = 255;
  }
  return rgba;
}

MotionField decode_motion(const std::vector<uint8_t>& rgba, int width, int height, float strength) {
  MotionField f;
  f.width = width;
  f.height = height;
  const size_t pixels = static_cast<size_t>(width) * height;
  f.uv.resize(pixels * 2);
  for (size_t i = 0; i < pixels; ++i) {
    f.uv[i * 2] = decode_component(rgba[i * 4], strength);
    f.uv[i * 2 + 1] = -decode_component(rgba[i * 4 + 1], strength);
  }
  return f;
}

}  // namespace pyro
