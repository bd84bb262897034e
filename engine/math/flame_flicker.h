#pragma once
// The flicker of a fire's light. A buoyant diffusion flame puffs: its luminous volume, and with it
// the light it sheds, pulses at a frequency set by its base diameter D,
//   f = 1.5 / sqrt(D) Hz, D in metres
// (Cetegen & Ahmed 1993, "Experiments on the periodic instability of buoyant plumes and pool
// fires", Combustion and Flame 93, the fit over pool fires of 0.03 to 50 m). The scale here is
//   1 + a n(t),   n(t) = sum_i c_i sin(2 pi r_i f t + phi_i) / sqrt(sum_i c_i^2 / 2),
// three partials at r = 0.62, 1, 1.53 of f (incommensurate, so the pulse never repeats exactly)
// with weights c = 0.5, 1, 0.5 and phases from `seed`: n has zero mean and unit rms, so `a` is
// the flicker's rms as a fraction of the mean. Clamped at 0.
#include <cstdint>

namespace pyro {

double puffing_frequency(double diameter_metres);

struct FlameFlicker {
  double amplitude = 0.0;  // rms of the scale's deviation from 1
  double frequency = 1.0;  // Hz, the puffing frequency
  uint32_t seed = 0;
};

double flame_flicker(const FlameFlicker& flicker, double seconds);

}  // namespace pyro
