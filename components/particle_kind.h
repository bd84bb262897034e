#pragma once
// What a ParticleSet's particles are drawn as, where its scene entry chose a kind of its own
// (clouds[].particles, emitters[].particles). A set without one is drawn as the scene-wide
// RenderSettings::particles. Read by the sorting system, which lists sets of different kinds in
// one back-to-front order with each entry's kind (components/draw_list.h), and by the billboard
// renderers, which draw that order in runs of one kind.
#include "components/render_modes.h"

namespace pyro {

struct ParticleKind {
  ParticleShape shape = ParticleShape::gaussian;
};

}  // namespace pyro
