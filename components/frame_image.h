#pragma once
// Resource: the last rendered frame read back from the GPU, linear RGBA floats, top row first,
// with the particle layer composited: the first (or only) view, and the right view in stereo.
// The readback system fills it; image tests and accuracy measurements read it.
#include <vector>

namespace pyro {

struct FrameImage {
  int width = 0, height = 0;
  std::vector<float> rgba;        // first view (mono, or the left eye)
  std::vector<float> right_rgba;  // right eye in stereo, else empty
  bool valid = false;
};

}  // namespace pyro
