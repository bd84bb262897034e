#pragma once
// A thick particle: one whose optical depth through its centre is at least 1, a centre opacity
// (the scene's cloud `density`) of at least 1 − e⁻¹ ≈ 0.632. Across such a particle the light
// changes, so the splats light it where the eye sees it (content/shaders/billboard.frag,
// THICK_PARTICLES) and the quality picker also tries the finer opacity shadow map for it.
#include <cmath>

namespace pyro {

inline bool thick_particle(float centre_opacity) {
  return centre_opacity >= static_cast<float>(-std::expm1(-1.0));
}

}  // namespace pyro
