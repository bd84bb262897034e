#pragma once
// A running world's particle media at this moment, as MediaSamples (media_sample.h): every live
// particle of density > 0 of every ParticleSet, in entity-index order, then every particle of
// extinction > 0 of every AnisotropicCloud. A set drawn as spheres (its ParticleKind, else the
// scene's RenderSettings::particles, spherical or planar) is the explosion's model with extinction
// density x opacity per unit length, as the billboards draw it; any other set is the clamped
// Gaussian of the splats, whose density is its centre opacity (engine/math/gaussian_line_integral.h).
#include <vector>

#include "engine/ecs/world.h"
#include "tools/export/media_sample.h"

namespace pyro {

std::vector<MediaSample> world_media(ecs::World& world);

}  // namespace pyro
