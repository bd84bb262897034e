#pragma once
// Resource: the last rendered frame read back from the GPU, linear RGBA floats, top row first.
// The output system fills it; PNG writing and image tests read it.
#include <vector>

namespace pyro {

struct FrameImage {
  int width = 0, height = 0;
  std::vector<float> rgba;
  bool valid = false;
};

}  // namespace pyro
