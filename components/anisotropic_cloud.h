#pragma once
// A static cloud of anisotropic Gaussian particles (engine/particles/anisotropic_gaussian.h) that
// an entity owns, e.g. a scene's `volumes[]` entry read from a version 2 particle file: fixed
// after loading, drawn by the billboard_render system each frame in back-to-front order per eye.
#include <vector>

#include "engine/particles/anisotropic_gaussian.h"

namespace pyro {

struct AnisotropicCloud {
  std::vector<AnisotropicGaussian> particles;
};

}  // namespace pyro
