#include "systems/flipbook_fire/flipbook_motion_blend.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pyro {

void sample_bilinear(const BlendImage& image, float u, float v, float* out) {
  const float fx = std::clamp(u * static_cast<float>(image.width) - 0.5f, 0.0f, static_cast<float>(image.width - 1));
  const float fy = std::clamp(v * static_cast<float>(image.height) - 0.5f, 0.0f, static_cast<float>(image.height - 1));
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float wx = fx - static_cast<float>(x0), wy = fy - static_cast<float>(y0);
  const int n = image.channels;
  auto at = [&](int x, int y, int c) {
    return image.values[(static_cast<size_t>(y) * image.width + x) * n + c];
  };
  for (int c = 0; c < n; ++c) {
    const float top = at(x0, y0, c) + wx * (at(x1, y0, c) - at(x0, y0, c));
    const float bottom = at(x0, y1, c) + wx * (at(x1, y1, c) - at(x0, y1, c));
    out[c] = top + wy * (bottom - top);
  }
}

namespace {

void check_same_size(const BlendImage& a, const BlendImage& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels ||
      a.values.size() != b.values.size())
    throw std::invalid_argument("flipbook blend: images of different sizes");
}

}  // namespace

BlendImage blend_linear(const BlendImage& a, const BlendImage& b, float t) {
  check_same_size(a, b);
  BlendImage out = a;
  for (size_t i = 0; i < out.values.size(); ++i) out.values[i] = (1.0f - t) * a.values[i] + t * b.values[i];
  return out;
}

BlendImage blend_motion_vectors(const BlendImage& a, const MotionField& ma, const BlendImage& b,
                                const MotionField& mb, float t) {
  check_same_size(a, b);
  if (ma.width != a.width || ma.height != a.height || mb.width != b.width || mb.height != b.height)
    throw std::invalid_argument("flipbook blend: motion of another size than its frame");
  BlendImage out = a;
  const int n = a.channels;
  std::vector<float> sa(static_cast<size_t>(n)), sb(static_cast<size_t>(n));
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(a.width);
      const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(a.height);
      sample_bilinear(a, u - t * ma.u(x, y), v - t * ma.v(x, y), sa.data());
      sample_bilinear(b, u + (1.0f - t) * mb.u(x, y), v + (1.0f - t) * mb.v(x, y), sb.data());
      float* o = &out.values[(static_cast<size_t>(y) * a.width + x) * n];
      for (int c = 0; c < n; ++c) o[c] = (1.0f - t) * sa[static_cast<size_t>(c)] + t * sb[static_cast<size_t>(c)];
    }
  return out;
}

double rmse(const BlendImage& a, const BlendImage& b) {
  check_same_size(a, b);
  double sum = 0.0;
  for (size_t i = 0; i < a.values.size(); ++i) {
    const double d = static_cast<double>(a.values[i]) - b.values[i];
    sum += d * d;
  }
  return a.values.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(a.values.size()));
}

}  // namespace pyro
