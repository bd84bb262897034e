#pragma once
// The GL state every particle pass draws with: depth tested against the opaque scene but not
// written, premultiplied "over" blending (ONE, ONE_MINUS_SRC_ALPHA) back to front, no culling.
#include <epoxy/gl.h>

namespace pyro {

inline void use_particle_blending() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
}

}  // namespace pyro
