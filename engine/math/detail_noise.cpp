#include "engine/math/detail_noise.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pyro {

namespace {

// A 64-bit mix (SplitMix64's finaliser) of the lattice point, octave and seed: every lattice
// value depends on nothing else, so the volume is the same on every machine and thread count.
uint64_t mix(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

float lattice(int x, int y, int z, int octave, uint64_t seed) {
  uint64_t h = mix(seed ^ mix(static_cast<uint64_t>(octave)));
  h = mix(h ^ static_cast<uint64_t>(static_cast<uint32_t>(x)));
  h = mix(h ^ static_cast<uint64_t>(static_cast<uint32_t>(y)));
  h = mix(h ^ static_cast<uint64_t>(static_cast<uint32_t>(z)));
  return static_cast<float>(h >> 40) / static_cast<float>(1ull << 24);  // [0, 1)
}

// Quintic fade 6t^5 - 15t^4 + 10t^3 (Perlin 2002): C2 across lattice cells.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

}  // namespace

DetailNoise make_detail_noise(int size, int base_cells, int octaves, uint64_t seed) {
  if (size <= 0 || base_cells <= 0 || octaves <= 0 || size % (base_cells << (octaves - 1)) != 0)
    throw std::invalid_argument("make_detail_noise: size must be a multiple of base_cells * 2^(octaves-1)");
  DetailNoise n;
  n.size = size;
  n.values.assign(static_cast<size_t>(size) * size * size, 0.0f);
  float amplitude = 1.0f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    const int cells = base_cells << o;       // lattice cells per period
    const float per_cell = static_cast<float>(size) / cells;  // texels per cell (integer)
    for (int z = 0; z < size; ++z)
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          const float fx = x / per_cell, fy = y / per_cell, fz = z / per_cell;
          const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
          const float tx = fade(fx - ix), ty = fade(fy - iy), tz = fade(fz - iz);
          auto v = [&](int dx, int dy, int dz) {
            // Wrap the lattice by its period: the volume tiles.
            return lattice((ix + dx) % cells, (iy + dy) % cells, (iz + dz) % cells, o, seed);
          };
          auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
          const float x00 = lerp(v(0, 0, 0), v(1, 0, 0), tx), x10 = lerp(v(0, 1, 0), v(1, 1, 0), tx);
          const float x01 = lerp(v(0, 0, 1), v(1, 0, 1), tx), x11 = lerp(v(0, 1, 1), v(1, 1, 1), tx);
          const float value = lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
          n.values[(static_cast<size_t>(z) * size + y) * size + x] += amplitude * value;
        }
    total += amplitude;
    amplitude *= 0.5f;
  }
  for (float& v : n.values) v = std::clamp(v / total, 0.0f, 1.0f);
  return n;
}

float detail_noise_at(const DetailNoise& n, int x, int y, int z) {
  auto wrap = [&](int i) { return ((i % n.size) + n.size) % n.size; };
  return n.values[(static_cast<size_t>(wrap(z)) * n.size + wrap(y)) * n.size + wrap(x)];
}

}  // namespace pyro

namespace pyro {

std::vector<float> detail_noise_slice_rg(const DetailNoise& noise, double t) {
  const int n = noise.size;
  std::vector<float> out(static_cast<size_t>(n) * n * 2);
  for (int channel = 0; channel < 2; ++channel) {
    const double tc = t + 0.5 * channel;
    const double z = (tc - std::floor(tc)) * n - 0.5;  // texel-centre coordinate
    const int z0 = static_cast<int>(std::floor(z));
    const float w = static_cast<float>(z - z0);
    const int dx = channel * n / 2, dy = channel * n / 4;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float a = detail_noise_at(noise, x + dx, y + dy, z0);
        const float b = detail_noise_at(noise, x + dx, y + dy, z0 + 1);
        out[(static_cast<size_t>(y) * n + x) * 2 + channel] = a + (b - a) * w;
      }
  }
  return out;
}

}  // namespace pyro
