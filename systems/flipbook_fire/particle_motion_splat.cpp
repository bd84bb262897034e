#include "systems/flipbook_fire/particle_motion_splat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pyro {

MotionSums::MotionSums(int w, int h)
    : width(w),
      height(h),
      weighted_uv(static_cast<size_t>(w) * h * 2, 0.0),
      weight(static_cast<size_t>(w) * h, 0.0) {}

void MotionSums::add(const MotionSums& other, double scale) {
  for (size_t i = 0; i < weight.size(); ++i) {
    weight[i] += scale * other.weight[i];
    weighted_uv[i * 2] += scale * other.weighted_uv[i * 2];
    weighted_uv[i * 2 + 1] += scale * other.weighted_uv[i * 2 + 1];
  }
}

namespace {

// One pass of the dilation: every empty pixel with filled neighbours (8-connected) takes their
// mean and becomes filled. Returns whether any pixel was filled.
bool dilate_once(MotionField& f, std::vector<uint8_t>& filled) {
  const std::vector<float> before = f.uv;
  const std::vector<uint8_t> was = filled;
  bool grew = false;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const size_t i = static_cast<size_t>(y) * f.width + x;
      if (was[i]) continue;
      float u = 0.0f, v = 0.0f;
      int n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= f.width || ny >= f.height) continue;
          const size_t j = static_cast<size_t>(ny) * f.width + nx;
          if (!was[j]) continue;
          u += before[j * 2];
          v += before[j * 2 + 1];
          ++n;
        }
      if (n == 0) continue;
      f.uv[i * 2] = u / static_cast<float>(n);
      f.uv[i * 2 + 1] = v / static_cast<float>(n);
      filled[i] = 1;
      grew = true;
    }
  return grew;
}

}  // namespace

MotionField MotionSums::field(int dilation) const {
  MotionField f;
  f.width = width;
  f.height = height;
  f.uv.assign(weighted_uv.size(), 0.0f);
  std::vector<uint8_t> filled(weight.size(), 0);
  for (size_t i = 0; i < weight.size(); ++i) {
    if (weight[i] <= 1e-12) continue;
    f.uv[i * 2] = static_cast<float>(weighted_uv[i * 2] / weight[i]);
    f.uv[i * 2 + 1] = static_cast<float>(weighted_uv[i * 2 + 1] / weight[i]);
    filled[i] = 1;
  }
  for (int pass = 0; pass < dilation && dilate_once(f, filled); ++pass) {
  }
  return f;
}

namespace {

// Adds one particle at pixel centre `c` (sums' pixels), footprint radius `r` pixels.
void splat_one(MotionSums& s, glm::vec2 c, float r, float weight, glm::vec2 motion_uv) {
  r = std::max(r, 0.75f);  // a particle smaller than a pixel still covers the one it falls in
  const int x0 = std::max(0, static_cast<int>(std::floor(c.x - r)));
  const int x1 = std::min(s.width - 1, static_cast<int>(std::ceil(c.x + r)));
  const int y0 = std::max(0, static_cast<int>(std::floor(c.y - r)));
  const int y1 = std::min(s.height - 1, static_cast<int>(std::ceil(c.y + r)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const float dx = static_cast<float>(x) + 0.5f - c.x, dy = static_cast<float>(y) + 0.5f - c.y;
      const float q = 1.0f - (dx * dx + dy * dy) / (r * r);
      if (q <= 0.0f) continue;
      const double w = static_cast<double>(weight) * q * q;
      const size_t i = static_cast<size_t>(y) * s.width + x;
      s.weight[i] += w;
      s.weighted_uv[i * 2] += w * motion_uv.x;
      s.weighted_uv[i * 2 + 1] += w * motion_uv.y;
    }
}

}  // namespace

void splat_particle_motion(const std::vector<MotionParticle>& particles, const CameraFrame& camera,
                           float dt, MotionSums& sums) {
  const glm::vec2 to_sums(static_cast<float>(sums.width) / static_cast<float>(camera.width),
                          static_cast<float>(sums.height) / static_cast<float>(camera.height));
  // Focal length in the sums' pixels (vertical field of view over the sums' height).
  const float focal = 0.5f * static_cast<float>(sums.height) / std::tan(0.5f * camera.fov_y_rad);
  for (const MotionParticle& p : particles) {
    const float depth = view_depth(camera, p.position);
    if (!(depth > camera.near) || !(p.weight > 0.0f)) continue;
    const glm::vec2 at = project_to_pixels(camera, p.position) * to_sums;
    const glm::vec2 to = project_to_pixels(camera, p.position + p.velocity * dt) * to_sums;
    const glm::vec2 motion_uv((to.x - at.x) / static_cast<float>(sums.width),
                              (to.y - at.y) / static_cast<float>(sums.height));
    splat_one(sums, at, p.radius * focal / depth, p.weight, motion_uv);
  }
}

}  // namespace pyro
