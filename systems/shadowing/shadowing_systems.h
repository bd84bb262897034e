#pragma once
// The light phase's shadowing (docs/lighting.md): in a world with a ShadowSettings resource,
// every particle set and anisotropic cloud gets a ParticleLight (the light reaching each
// particle), and the opaque
// pass a ShadowVolume, once per frame whatever the number of eyes. Two methods, each a system:
//  - shadow_map: the opacity shadow map (opacity_shadow_map.h), built when the particles use it
//    or opaque surfaces receive it; with ShadowMethod::shadow_map (or none) it also lights the
//    particles, from the map at their centres (or with transmittance 1);
//  - shadow_rays: with ShadowMethod::rays, the exact transmittance at each particle's centre
//    (engine/math/shadow_ray_index.h).
#include <vector>

#include "engine/ecs/schedule.h"
#include "engine/ecs/world.h"
#include "engine/math/shadow_caster.h"

namespace pyro {

// Every live particle of the world's particle sets with density > 0, in entity-index order, then
// every particle of the anisotropic clouds with extinction > 0: the media that cast shadows.
// Gaussians, or with the explosion's media layers (RenderSettings::media_layers) spheres whose
// extinction is the particle's density times its opacity, as the billboards draw them; the
// clouds' ellipsoids.
std::vector<ShadowCaster> shadow_casters(ecs::World& world);

ecs::SystemDesc shadow_map_system();
ecs::SystemDesc shadow_ray_system();

}  // namespace pyro
