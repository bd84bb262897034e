#include "engine/math/value_noise.h"

#include <cmath>

#include "engine/core/rng.h"

namespace pyro {

namespace {

float hashed_lattice_value(int32_t x, int32_t y, int32_t z, uint64_t seed) {
  uint64_t s = seed ^ (static_cast<uint64_t>(static_cast<uint32_t>(x)) * 0x9E3779B185EBCA87ull) ^
               (static_cast<uint64_t>(static_cast<uint32_t>(y)) * 0xC2B2AE3D27D4EB4Full) ^
               (static_cast<uint64_t>(static_cast<uint32_t>(z)) * 0x165667B19E3779F9ull);
  const uint64_t h = splitmix64(s);
  return static_cast<float>(h >> 40) * (2.0f / 16777216.0f) - 1.0f;  // [−1, 1)
}

// Quintic fade 6t⁵ − 15t⁴ + 10t³ (Perlin 2002) and its derivative 30t²(t − 1)².
inline float quintic_fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
inline float quintic_fade_derivative(float t) { return 30.0f * t * t * (t - 1.0f) * (t - 1.0f); }

}  // namespace

float value_noise(const glm::vec3& p, uint64_t seed, glm::vec3* gradient) {
  const float fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  const auto ix = static_cast<int32_t>(fx), iy = static_cast<int32_t>(fy), iz = static_cast<int32_t>(fz);
  const float u[3] = {p.x - fx, p.y - fy, p.z - fz};
  float w[3][2], dw[3][2];
  for (int a = 0; a < 3; ++a) {
    const float s = quintic_fade(u[a]), ds = quintic_fade_derivative(u[a]);
    w[a][0] = 1.0f - s;
    w[a][1] = s;
    dw[a][0] = -ds;
    dw[a][1] = ds;
  }
  float n = 0.0f;
  glm::vec3 g(0.0f);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const float v = hashed_lattice_value(ix + i, iy + j, iz + k, seed);
        n += v * w[0][i] * w[1][j] * w[2][k];
        g.x += v * dw[0][i] * w[1][j] * w[2][k];
        g.y += v * w[0][i] * dw[1][j] * w[2][k];
        g.z += v * w[0][i] * w[1][j] * dw[2][k];
      }
  if (gradient) *gradient = g;
  return n;
}

}  // namespace pyro
