#pragma once
// Deterministic random streams. Every stream is seeded from the scene (scene seed mixed with a
// per-emitter seed), so the same scene gives the same particles on any machine and thread count.
#include <cstdint>

namespace pyro {

// SplitMix64 (Steele, Lea & Flood 2014): a good 64-bit mixer, used to derive stream seeds.
constexpr uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr uint64_t mix_seeds(uint64_t a, uint64_t b) {
  uint64_t s = a ^ (b * 0xD1342543DE82EF95ull);
  return splitmix64(s);
}

// PCG32 (O'Neill 2014, XSH RR variant): small state, fast, statistically sound.
class Rng {
 public:
  explicit constexpr Rng(uint64_t seed, uint64_t stream = 0x14057B7EF767814Full)
      : state_(0), inc_((stream << 1u) | 1u) {
    next_u32();
    state_ += seed;
    next_u32();
  }

  constexpr uint32_t next_u32() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits make every value exactly representable as a float.
  constexpr float uniform() { return static_cast<float>(next_u32() >> 8) * (1.0f / 16777216.0f); }
  constexpr float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

 private:
  uint64_t state_;
  uint64_t inc_;
};

}  // namespace pyro
