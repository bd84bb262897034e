#pragma once
// Resource: the camera's matrices for this frame, written by the camera system.
#include "engine/math/camera_math.h"

namespace pyro {

struct View {
  CameraFrame frame;
};

}  // namespace pyro
