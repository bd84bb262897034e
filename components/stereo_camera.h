#pragma once
// Makes a Camera entity stereo: two eyes from off-axis projections with parallel view axes
// (engine/math/stereo_projection.h). Both eyes render the same simulation state.
#include "engine/math/stereo_projection.h"

namespace pyro {

struct StereoCamera {
  StereoParameters parameters;
};

}  // namespace pyro
