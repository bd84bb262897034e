#pragma once
// Resource: the light the explosion's fire gives its dust, smoke and the ground (docs/lighting.md),
// written every frame by the light phase (systems/lighting/fire_lights.h) in a world whose scene
// is lit (a ShadowSettings resource) and whose particles are the explosion's media. Each fire
// particle is a point emitter of intensity L_e(T) A (its black-body radiance times its opacity
// integrated over its disc); the renderers shade with a few lights clustered from them.
#include <vector>

#include "engine/math/point_light_clusters.h"

namespace pyro {

// The most lights the shaders take.
inline constexpr int kMaxFireLights = 8;

struct FireLights {
  std::vector<PointEmitter> lights;    // at most kMaxFireLights, world space
  std::vector<PointEmitter> emitters;  // every fire particle: the truth the lights stand for
};

}  // namespace pyro
