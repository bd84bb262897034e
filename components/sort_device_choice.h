#pragma once
// Resource: which device makes the Gaussian splats' draw order when the scene leaves it to the
// engine (SortDevice::automatic), and the measurement that chose it. The billboard_render system
// measures both on the running renderer: the sorting system's CPU time for a frame's order (its
// keys and radix order) against the same order made by the compute shaders (dispatch to
// completion, after a warm-up run). It measures on the second frame at a particle count, so that
// the CPU's time is not the first frame's, which grows its working space. The sorting system
// reads `gpu` on the frames after.
#include <cstdint>

namespace pyro {

struct SortDeviceChoice {
  bool gpu = false;          // the GPU's order was the faster when last measured
  bool measured = false;     // false until the first measurement
  double cpu_ms = 0.0;       // the CPU's keys and order, per order, in the measured frame
  double gpu_ms = 0.0;       // the compute shaders' order of the same particles
  uint64_t particles = 0;    // the particles in the sets when measured
  uint64_t last_frame_particles = 0;  // the particles in the frame before, while the CPU orders
  // Measure again once the particle count has grown this many times over (a scene that starts
  // with few particles would otherwise keep the choice made for them).
  static constexpr double kRemeasureGrowth = 4.0;
  bool needs_measuring(uint64_t now) const {
    return !measured || double(now) >= kRemeasureGrowth * double(particles);
  }
  // Whether the frame before had about as many particles (at most twice fewer): the CPU's
  // working space has grown to this count.
  bool steady(uint64_t now) const { return last_frame_particles > 0 && now <= 2 * last_frame_particles; }
};

}  // namespace pyro
