#include "systems/volume_sequence/sequence_clock.h"

#include <algorithm>
#include <cmath>

namespace pyro {

double sequence_position(uint64_t frame, double runtime_fps, double frames_per_second, std::size_t start) {
  const double s = double(start) + double(frame) * frames_per_second / runtime_fps;
  const double nearest = std::round(s);
  return std::abs(s - nearest) <= 1e-6 * std::max(1.0, nearest) ? nearest : s;
}

SequenceSample sample_sequence(double s, std::size_t count, bool loop) {
  const double n = double(count);
  if (loop) {
    s = std::fmod(s, n);
    if (s < 0.0) s += n;
  } else if (s >= n - 1.0) {
    return {count - 1, count - 1, 0.0};
  }
  std::size_t a = static_cast<std::size_t>(std::floor(s));
  if (a >= count) a = count - 1;
  const double w = s - double(a);
  if (w <= 0.0) return {a, a, 0.0};
  return {a, (a + 1) % count, w};
}

}  // namespace pyro
