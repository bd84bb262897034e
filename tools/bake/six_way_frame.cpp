#include "tools/bake/six_way_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pyro {

namespace {

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

uint8_t to_byte_linear(float v) { return static_cast<uint8_t>(std::lround(clamp01(v) * 255.0f)); }

float mean_rgb(const RgbImage& image, size_t pixel) {
  const float* p = &image.rgb[3 * pixel];
  return (p[0] + p[1] + p[2]) / 3.0f;
}

}  // namespace

SixWayValues SixWayFrame::faces_at(size_t pixel) const {
  SixWayValues v{};
  for (int i = 0; i < kSixWayFaces; ++i) v[i] = faces[i][pixel];
  return v;
}

SixWayFrame blank_six_way_frame(int width, int height) {
  SixWayFrame frame;
  frame.width = width;
  frame.height = height;
  const size_t pixels = static_cast<size_t>(width) * height;
  for (std::vector<float>& face : frame.faces) face.assign(pixels, 0.0f);
  frame.alpha.assign(pixels, 0.0f);
  frame.emissive.assign(pixels, 0.0f);
  return frame;
}

SixWayFrame six_way_frame_from_renders(const std::array<RgbImage, kSixWayFaces>& faces,
                                       const RgbImage& opacity) {
  for (const RgbImage& face : faces)
    if (face.width != opacity.width || face.height != opacity.height)
      throw std::invalid_argument("six_way_frame_from_renders: renders differ in size");
  SixWayFrame frame = blank_six_way_frame(opacity.width, opacity.height);
  for (size_t p = 0; p < frame.alpha.size(); ++p) {
    const float alpha = clamp01(mean_rgb(opacity, p));
    frame.alpha[p] = alpha;
    for (int i = 0; i < kSixWayFaces; ++i)
      frame.faces[i][p] = alpha > 0.0f ? clamp01(mean_rgb(faces[i], p) / alpha) : 0.0f;
  }
  return frame;
}

SixWayTextures pack_six_way(const SixWayFrame& frame) {
  SixWayTextures t;
  t.width = frame.width;
  t.height = frame.height;
  const size_t pixels = frame.alpha.size();
  t.a.resize(pixels * 4);
  t.b.resize(pixels * 4);
  for (size_t p = 0; p < pixels; ++p) {
    const auto face = [&](SixWayFace f) {
      return to_byte_linear(frame.faces[static_cast<int>(f)][p]);
    };
    t.a[4 * p + 0] = face(SixWayFace::right);
    t.a[4 * p + 1] = face(SixWayFace::top);
    t.a[4 * p + 2] = face(SixWayFace::back);
    t.a[4 * p + 3] = to_byte_linear(frame.alpha[p]);
    t.b[4 * p + 0] = face(SixWayFace::left);
    t.b[4 * p + 1] = face(SixWayFace::bottom);
    t.b[4 * p + 2] = face(SixWayFace::front);
    t.b[4 * p + 3] = to_byte_linear(frame.emissive[p]);
  }
  return t;
}

SixWayFrame unpack_six_way(const SixWayTextures& t) {
  SixWayFrame frame = blank_six_way_frame(t.width, t.height);
  const size_t pixels = frame.alpha.size();
  if (t.a.size() != pixels * 4 || t.b.size() != pixels * 4)
    throw std::invalid_argument("unpack_six_way: textures differ from their size");
  const auto value = [](uint8_t byte) { return byte / 255.0f; };
  for (size_t p = 0; p < pixels; ++p) {
    const auto set = [&](SixWayFace f, uint8_t byte) {
      frame.faces[static_cast<int>(f)][p] = value(byte);
    };
    set(SixWayFace::right, t.a[4 * p + 0]);
    set(SixWayFace::top, t.a[4 * p + 1]);
    set(SixWayFace::back, t.a[4 * p + 2]);
    frame.alpha[p] = value(t.a[4 * p + 3]);
    set(SixWayFace::left, t.b[4 * p + 0]);
    set(SixWayFace::bottom, t.b[4 * p + 1]);
    set(SixWayFace::front, t.b[4 * p + 2]);
    frame.emissive[p] = value(t.b[4 * p + 3]);
  }
  return frame;
}

RgbImage relight_six_way(const SixWayFrame& frame, const glm::vec3& towards_light,
                         const glm::vec3& light_color) {
  RgbImage out;
  out.width = frame.width;
  out.height = frame.height;
  out.rgb.assign(frame.alpha.size() * 3, 0.0f);
  const SixWayValues weights = six_way_weights(towards_light);
  for (size_t p = 0; p < frame.alpha.size(); ++p) {
    float lighting = 0.0f;
    for (int i = 0; i < kSixWayFaces; ++i) lighting += weights[i] * frame.faces[i][p];
    for (int c = 0; c < 3; ++c)
      out.rgb[3 * p + c] = (light_color[c] * lighting + frame.emissive[p]) * frame.alpha[p];
  }
  return out;
}

SixWayFrame cross_fade_six_way(const SixWayFrame& a, const SixWayFrame& b, float w) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("cross_fade_six_way: frames differ in size");
  SixWayFrame out = blank_six_way_frame(a.width, a.height);
  for (size_t p = 0; p < out.alpha.size(); ++p) {
    const float alpha = w * a.alpha[p] + (1.0f - w) * b.alpha[p];
    out.alpha[p] = alpha;
    const auto mix = [&](float va, float vb) {
      return alpha > 0.0f ? clamp01((w * va * a.alpha[p] + (1.0f - w) * vb * b.alpha[p]) / alpha)
                          : 0.0f;
    };
    for (int i = 0; i < kSixWayFaces; ++i) out.faces[i][p] = mix(a.faces[i][p], b.faces[i][p]);
    out.emissive[p] = mix(a.emissive[p], b.emissive[p]);
  }
  return out;
}

}  // namespace pyro
