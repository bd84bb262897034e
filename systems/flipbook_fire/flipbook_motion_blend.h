#pragma once
// Playing a flipbook between its frames, on the CPU (the charts and tests; the GPU does the same
// in content/shaders/flipbook.frag). At fraction t in [0, 1] of the way from frame a to frame b:
//   linear:        out(uv) = (1 - t) a(uv) + t b(uv)
//   motion vectors: out(uv) = (1 - t) a(uv - t m_a(uv)) + t b(uv + (1 - t) m_b(uv))
// the standard motion-vector flipbook blend (as Unity's Flipbook Motion Blend and Unreal's
// FlipBook_MotionVectors do it): frame a is pushed forward along its own motion by t of a frame,
// frame b pulled back along its own by the rest, so that features meet where they are at t
// instead of fading out in one place and in at another. Images are any number of float channels
// (linear light for colour), top row first, sampled bilinearly with clamped edges at pixel
// centres; motion is in frame UV units (flipbook_motion.h).
#include <vector>

#include "systems/flipbook_fire/flipbook_motion.h"

namespace pyro {

struct BlendImage {
  int width = 0, height = 0, channels = 4;
  std::vector<float> values;
};

BlendImage blend_linear(const BlendImage& a, const BlendImage& b, float t);
BlendImage blend_motion_vectors(const BlendImage& a, const MotionField& motion_a, const BlendImage& b,
                                const MotionField& motion_b, float t);

// Bilinear sample of channel values at frame uv (pixel centres at (x + 0.5) / width), edges
// clamped; writes `channels` floats to `out`.
void sample_bilinear(const BlendImage& image, float u, float v, float* out);

// Root mean square difference over every value (channels included).
double rmse(const BlendImage& a, const BlendImage& b);

}  // namespace pyro
