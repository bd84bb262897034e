#include "engine/math/flipbook_sequence.h"

#include <cmath>
#include <stdexcept>

namespace pyro {

int flipbook_frame(int64_t start, int64_t increment, int64_t step, int frame_count) {
  if (frame_count <= 0) throw std::invalid_argument("flipbook_frame: frame count must be positive");
  const int64_t n = frame_count;
  // Reduce each term first so that the product cannot overflow.
  const int64_t s = ((start % n) + n) % n;
  const int64_t m = ((increment % n) + n) % n;
  const int64_t t = step % n;
  return static_cast<int>((s + (m * t) % n) % n);
}

int64_t flipbook_step(double seconds, double frames_per_second) {
  return static_cast<int64_t>(std::floor(seconds * frames_per_second + 1e-6));
}

}  // namespace pyro
