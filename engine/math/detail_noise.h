#pragma once
// The animated detail texture of Umenhoffer et al. 2006, section 3: the paper perturbs each
// particle's opacity (dust, smoke) or temperature (fire) with a grey-scale video of real smoke
// stored as a 3D texture (x, y, time). No video ships with the engine; it makes the volume
// itself: fractal value noise (sum of octaves of quintic-interpolated lattice noise, each octave
// at twice the frequency and half the amplitude), periodic on every axis so GL_REPEAT loops it
// in space and in time. Values lie in [0, 1]. Deterministic from the seed.
#include <cstdint>
#include <vector>

namespace pyro {

struct DetailNoise {
  int size = 0;               // size^3 texels, x fastest, then y, then z (time)
  std::vector<float> values;  // in [0, 1]
};

// `size` texels per side (a multiple of 2^(octaves-1) times `base_cells`), `base_cells` lattice
// cells per period for the first octave.
DetailNoise make_detail_noise(int size = 64, int base_cells = 4, int octaves = 3, uint64_t seed = 1);

// The texel value at integer coordinates, wrapped periodically.
float detail_noise_at(const DetailNoise& noise, int x, int y, int z);

}  // namespace pyro
