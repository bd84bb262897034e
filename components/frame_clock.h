#pragma once
// Resource: the simulation clock. Time is frame * dt, never accumulated, so any frame can be
// reached directly and two runs agree bit for bit.
#include <cstdint>

namespace pyro {

struct FrameClock {
  uint64_t frame = 0;
  float dt = 1.0f / 30.0f;  // seconds per frame
  double time() const { return static_cast<double>(frame) * dt; }
};

}  // namespace pyro
