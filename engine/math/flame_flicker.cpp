#include "engine/math/flame_flicker.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pyro {

namespace {

constexpr double kPartialRatio[3] = {0.62, 1.0, 1.53};
constexpr double kPartialWeight[3] = {0.5, 1.0, 0.5};

// A phase in [0, 2 pi) per partial from the seed (splitmix64's finaliser).
double partial_phase(uint32_t seed, int partial) {
  uint64_t z = (uint64_t(seed) << 8 | uint64_t(partial)) + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return 2.0 * std::numbers::pi * double(z >> 11) / double(1ull << 53);
}

}  // namespace

double puffing_frequency(double diameter_metres) { return 1.5 / std::sqrt(std::max(diameter_metres, 1e-6)); }

double flame_flicker(const FlameFlicker& flicker, double seconds) {
  if (flicker.amplitude <= 0.0) return 1.0;
  double sum = 0.0, power = 0.0;
  for (int i = 0; i < 3; ++i) {
    sum += kPartialWeight[i] *
           std::sin(2.0 * std::numbers::pi * kPartialRatio[i] * flicker.frequency * seconds +
                    partial_phase(flicker.seed, i));
    power += 0.5 * kPartialWeight[i] * kPartialWeight[i];
  }
  return std::max(0.0, 1.0 + flicker.amplitude * sum / std::sqrt(power));
}

}  // namespace pyro
