#pragma once
// Which flame frame a flipbook billboard shows (Rose 2007, section 4.4): billboard k starts at
// frame s_k and steps by its increment m_k every time step, looping over the n frames:
//   frame_k(t) = (s_k + t m_k) mod n, in [0, n), for increments and starts of either sign.
#include <cstdint>

namespace pyro {

// n > 0; t >= 0. Exact in 64-bit integers for |s|, |m| below 2^31 and t below 2^31.
int flipbook_frame(int64_t start, int64_t increment, int64_t step, int frame_count);

// The flipbook time step at scene time `seconds` for `frames_per_second` steps per second:
// floor(seconds fps), nudged by 1e-6 so that a time computed as frame dt lands on its step.
int64_t flipbook_step(double seconds, double frames_per_second);

}  // namespace pyro
