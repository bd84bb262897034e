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

namespace pyro {

// The volume's slice at time t (in periods: z = t * size texel units, texel centres at
// z + 1/2), linearly interpolated between the two nearest z layers, as two interleaved channels
// (x fastest, size^2 texels): r is the slice at t, g the slice at t + 1/2 shifted by half a
// period in x and a quarter in y — two independent-looking fields. Sampled bilinearly with
// repeat, it equals trilinear sampling of the volume at (u, v, t) and at (u + 1/2, v + 1/4,
// t + 1/2): the heat shimmer's two offsets (systems/composite) at one fetch a pixel.
std::vector<float> detail_noise_slice_rg(const DetailNoise& noise, double t);

}  // namespace pyro
