#pragma once
// Resource: this frame's views, written by the camera system: the mono (centre) frame and the
// frames actually rendered (one for mono output, left then right for stereo).
#include <vector>

#include "engine/math/camera_math.h"

namespace pyro {

struct View {
  CameraFrame frame;                // the mono camera (the mid-eye position in stereo)
  std::vector<CameraFrame> eyes;    // rendered views
};

}  // namespace pyro
